// SPDX-License-Identifier: MIT
// A bicubic polynomial Bezier patch in the power basis: the surface the error
// bounds (error_bound.h) evaluate millions of times, at about a third of the
// instructions of the Bernstein form (docs/results/tessellation.md, fifth
// pass). S(s, t) = o + sum_ij a_ij s^i t^j, i, j = 0..3, with o the control
// point (0, 0) (so the coefficients scale with the patch's extent, not with
// its coordinates' magnitude); each row sum_j a_ij t^j and then the sum over
// i by Horner's rule.
//
// Rounding. The point differs from the exact surface point by at most
// `error` (model units), a bound proven once per patch from the computed
// coefficients (Higham, Accuracy and Stability of Numerical Algorithms, 5.1:
// Horner's rule of degree n is within gamma_2n sum |a_k| |x|^k, gamma_n =
// n u / (1 - n u)): the conversion's sums of at most four integer multiples,
// the two nested Horner passes, the rounded differences P - o (a convex
// combination of them, so at most u max |P - o|) and the final + o. The bound
// adds it to its rounding allowance. The derivatives only steer the feet's
// Gauss-Newton steps, where any value keeps the bound valid.
#pragma once

#include <seamless/spline/bezier_patch.h>

namespace seamless {

struct PowerBasisPatch {
    Vec3 origin;
    // a[c][j][i]: coordinate c's coefficient of s^i t^j (rows contiguous in i).
    alignas(16) double a[3][4][4] = {};
    // The t-derivative's coefficients of s^i t^j, j = 0..2: a[c][j + 1][i] (j + 1).
    alignas(16) double at[3][3][4] = {};
    double error = 0; // bound on |computed point - S(s, t)| for s, t in [0, 1]
};

// Only for a polynomial bicubic patch (p = q = 3, every weight 1).
bool has_power_basis(const BezierPatch& b);
// rounding_bound false: `error` left 0 (for estimates, not proofs).
PowerBasisPatch power_basis(const BezierPatch& b, bool rounding_bound = true);

// Point and derivatives with respect to the local (s, t), s, t in [0, 1].
SurfacePoint evaluate(const PowerBasisPatch& pb, double s, double t);
// The point alone: the same value as evaluate(pb, s, t).point.
Vec3 evaluate_point(const PowerBasisPatch& pb, double s, double t);

} // namespace seamless
