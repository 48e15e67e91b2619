// SPDX-License-Identifier: MIT
// A subpatch: the Bernstein coefficients of a Bezier patch restricted to a
// parameter box (paper section 4: a Bezier patch is subdivided by de
// Casteljau's algorithm). The coefficients are intervals that enclose the exact
// coefficients of the restriction, so by the convex hull property every range
// over the box is enclosed by the hull of a few of them: no Horner, no Lemma 2.
// Coefficient blocks live in flat arrays owned by the caller (dim x (p+1) x
// (q+1) intervals, sized by the patch's degree): nothing allocated per call.
#pragma once

#include <seamless/interval/interval.h>
#include <seamless/interval/interval_matrix.h>
#include <seamless/spline/bezier_patch.h>

#include <type_traits>

namespace seamless {

struct SubpatchShape {
    int p = 0, q = 0; // degrees in s and t
    int dim = 3;      // homogeneous coordinates kept: (wx, wy, wz), and w when rational
    int size() const { return dim * (p + 1) * (q + 1); }
    int index(int c, int i, int j) const { return (c * (p + 1) + i) * (q + 1) + j; }
};

// f(n) for a degree n of a subpatch's rows, with n a std::integral_constant
// for degrees 1 to 3 (the common bilinear, biquadratic and bicubic patches)
// so that loops over it unroll, and the int itself otherwise: f must be
// written for either (same operations, so the same bits).
template <class F> decltype(auto) with_degree(int n, F f) {
    switch (n) {
    case 1:
        return f(std::integral_constant<int, 1>{});
    case 2:
        return f(std::integral_constant<int, 2>{});
    case 3:
        return f(std::integral_constant<int, 3>{});
    default:
        return f(n);
    }
}

// dim 3 for a polynomial patch (w = 1 everywhere), 4 for a rational one.
SubpatchShape subpatch_shape(const BezierPatch& b);
// The control points themselves: the subpatch over [0,1]^2 (exact doubles).
void control_coefficients(const BezierPatch& b, SubpatchShape sh, Interval* out);

// Restricts, in place, the subpatch in direction dir (0: s, 1: t) from its
// local [0,1] to local [u0, u1] (0 <= u0 <= u1 <= 1). u0 and u1 are intervals
// holding the exact ends; the result encloses the coefficients for every end
// in them. A thin u0 = 0 or u1 = 1 skips its de Casteljau pass.
void restrict_subpatch(Interval* c, SubpatchShape sh, int dir, Interval u0, Interval u1);

// The subpatch c split at local u in direction dir: lo over [0, u], hi over
// [u, 1], bit for bit restrict_subpatch(copy, sh, dir, 0, u) and
// restrict_subpatch(copy, sh, dir, u, 1), from one de Casteljau triangle per
// row instead of two (a bisection's halves).
void split_subpatch(const Interval* c, SubpatchShape sh, int dir, Interval u, Interval* lo,
                    Interval* hi);

// Enclosure of the camera-space point X / W over the subpatch's box: the hull
// of the projected control points (convex hull property; it needs weights
// > 0: where a w coefficient is not certainly positive the hull is entire).
IVec<3> subpatch_hull(const Interval* c, SubpatchShape sh);
// Enclosure of the screen point (X / Z, Y / Z) over the box when every z
// coefficient is positive (the projection is a rational Bezier patch with
// weights z_ij); false otherwise.
bool subpatch_projection(const Interval* c, SubpatchShape sh, Interval& a, Interval& b);

} // namespace seamless
