// SPDX-License-Identifier: MIT
// The cluster of primary rays through a sub-screen against one patch (paper
// section 5, Theorem 10 and its remarks; Theorem 6 for the certificate). In
// camera coordinates a point is on the ray through screen point (a, b) iff
// X - a Z = 0 and Y - b Z = 0 on the homogeneous coordinates (W cancels), so
// the sub-screen [a] x [b] poses a two-dimensional interval system G(s, t).
#pragma once

#include <seamless/spline/enclosure.h>
#include <seamless/spline/power_form.h>
#include <seamless/spline/subpatch.h>

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

// Theorem 10's narrowing on a subpatch (subpatch.h): the parameters where G
// may vanish for some ray of the cluster, found from the Bernstein coefficients
// g_ij = x_ij - [a] z_ij instead of derivative ranges (Bezier clipping): for
// every v, (u, G(u, v)) lies in the convex hull of the points (i / p, g_i.(v))
// (linear precision of the Bernstein basis), so G vanishes only where the hull
// of the columns (i / p, hull_j g_ij) meets 0; the same along t. c: the
// subpatch's coefficients (shape sh), over its own box [0,1]^2. Returns false
// when no ray of the cluster meets the subpatch; otherwise u, v are the local
// parameter ranges (in [0,1]) holding every zero. D: when given, ranges of
// (G_k)_u, (G_k)_v over the subpatch times positive factors (1/p, 1/q), enough
// for the sign of the Jacobian's determinant (left as it was when false).
bool clip_cluster(const Interval* c, SubpatchShape sh, Interval a, Interval b, Interval& u,
                  Interval& v, IMat<2>* D = nullptr);

// The pieces of clip_cluster for G_k = X_k - e Z (e = a for k = 0, b for
// k = 1): the hulls of its Bernstein coefficients over each column i
// (col[0..p]) and row j (row[0..q]), and the hulls du, dv of their s- and
// t-differences (x and z differenced first, so e enters once; 0 along a
// degree-0 direction). lanes: computed on lane pairs (interval/lanes.h), bit
// for bit the scalar results, allowed only where cluster_lanes_apply holds
// (every bound of a, b and of the x, y, z coefficients below 2^500).
bool cluster_lanes_apply(const Interval* c, SubpatchShape sh, Interval a, Interval b);
void coefficient_hulls(const Interval* c, SubpatchShape sh, Interval e, int k, Interval* col,
                       Interval* row, bool lanes);
void difference_ranges(const Interval* c, SubpatchShape sh, Interval e, int k, Interval& du,
                       Interval& dv, bool lanes);

// Both rows at once: D(k, 0), D(k, 1) = du, dv of G_k (the same bits as
// difference_ranges for k = 0 and 1; the z differences formed once).
void cluster_differences(const Interval* c, SubpatchShape sh, Interval a, Interval b, IMat<2>& D,
                         bool lanes);

// The interval Jacobian of G with respect to the global (s, t) over a
// subpatch's box (its coefficients c over exactly `box`): p times the hull of
// the s-differences of the coefficients divided by the box's width, and the
// same along t; entire entries where the box is too thin to divide by.
IMat<2> subpatch_jacobian(const Interval* c, SubpatchShape sh, const ParamBox& box, Interval a,
                          Interval b);

// The hull over j of G_k's Bernstein coefficients in row i = 0 or p (dir 0),
// column j = 0 or q (dir 1): the range of G_k along that edge of the subpatch.
Interval edge_range(const Interval* c, SubpatchShape sh, Interval a, Interval b, int k, int dir,
                    bool far);

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
