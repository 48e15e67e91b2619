// SPDX-License-Identifier: MIT
// The cluster of primary rays through a sub-screen against one patch (paper
// section 5, Theorem 10 and its remarks; Theorem 6 for the certificate). In
// camera coordinates a point is on the ray through screen point (a, b) iff
// X - a Z = 0 and Y - b Z = 0 on the homogeneous coordinates (W cancels), so
// the sub-screen [a] x [b] poses a two-dimensional interval system G(s, t).
// Here G is taken in power form (the paper's derivative ranges by Horner); the
// same narrowing on a mark's Bernstein coefficients is bezier_clip.h's.
#pragma once

#include <seamless/spline/enclosure/enclosure.h>
#include <seamless/spline/enclosure/power_form.h>
#include <seamless/spline/enclosure/subpatch.h>

namespace seamless {

// G = (X - [a] Z, Y - [b] Z) and its partial derivatives, in power form.
struct ClusterSystem {
    PowerForm G, Gs, Gt;
    // The patch's forms and the screen ranges G was formed from, set with G by
    // cluster_system (its only writer): certify_steps takes G at a point as
    // X - [a] Z, [a] multiplied once, instead of Horner on G's coefficients,
    // each of which carries [a]. X points into the caller's PatchForms.
    const PowerForm* X = nullptr;
    Interval a, b;
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

// certify_cluster in pieces, for a caller that may give up between them
// (cluster_attempt.h): cluster_start(box) is the first box x, certify_steps
// takes at most `iterations` steps from x (left as the next start) and says
// whether they proved the cluster (box contracted), proved nothing more can
// come of it (failed), or ran out (open). certify_cluster is
// certify_steps(sys, cluster_start(box), box, kClusterCertifySteps) == proven.
enum class ClusterCertificate { proven, failed, open };
constexpr int kClusterCertifySteps = 6;
IVec<2> cluster_start(const ParamBox& box);
ClusterCertificate certify_steps(const ClusterSystem& sys, IVec<2>& x, ParamBox& box,
                                 int iterations, long long* steps = nullptr);

} // namespace seamless
