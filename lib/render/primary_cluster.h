// SPDX-License-Identifier: MIT
// The cluster of primary rays through a sub-screen against one patch (paper
// section 5, Theorem 10 and its remarks; Theorem 6 for the certificate). In
// camera coordinates a point is on the ray through screen point (a, b) iff
// X - a Z = 0 and Y - b Z = 0 on the homogeneous coordinates (W cancels), so
// the sub-screen [a] x [b] poses a two-dimensional interval system G(s, t).
#pragma once

#include <seamless/spline/enclosure.h>
#include <seamless/spline/power_form.h>

namespace seamless {

// G = (X - [a] Z, Y - [b] Z) and its partial derivatives, in power form.
struct ClusterSystem {
    PowerForm G, Gs, Gt;
};
void cluster_system(const PatchForms& f, Interval a, Interval b, ClusterSystem& out);

// Pieces of {x in X : 0 in n + d (x - x0)}, at most two (extended division;
// Theorem 10 remark 5). Returns how many are non-empty.
int solve_pieces(Interval n, Interval d, Interval X, double x0, Interval out[2]);

// Theorem 10 with remark 3: narrows box in s and t, solving at both bounds.
// Returns false when the patch certainly misses every ray of the cluster.
// jacobian: when given, the ranges of G_s and G_t of the last pass, taken
// over boxes that hold the narrowed box (so they enclose G' over it).
bool narrow(const ClusterSystem& sys, ParamBox& box, IMat<2>* jacobian = nullptr);

// Remark 3: where a silhouette is possible, solve at the midpoints too; when
// that leaves two separate pieces, the patch is separated into two boxes.
// Returns how many boxes (0: no ray meets the patch in box).
int separate(const ClusterSystem& sys, const ParamBox& box, ParamBox out[2]);

// Theorem 6 iii over the whole cluster: true when every ray of the cluster has
// exactly one zero of G in `box`, which is then contracted around them.
// Adds the Hansen-Sengupta steps taken to *steps when given.
bool certify_cluster(const ClusterSystem& sys, ParamBox& box, long long* steps = nullptr);

} // namespace seamless
