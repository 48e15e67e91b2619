// SPDX-License-Identifier: MIT
// Theorem 10's narrowing by Bezier clipping (paper section 5; INTRACY step 3,
// mark.h): the cluster of primary rays through a sub-screen [a] x [b] poses
// G = (X - [a] Z, Y - [b] Z) (primary_cluster.h), here on a subpatch's
// Bernstein coefficients (subpatch.h) instead of derivative ranges, with the
// coefficients' differences for the Jacobian of G over the subpatch.
#pragma once

#include <seamless/interval/interval_matrix.h>
#include <seamless/spline/enclosure/enclosure.h>
#include <seamless/spline/enclosure/subpatch.h>

namespace seamless {

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

} // namespace seamless
