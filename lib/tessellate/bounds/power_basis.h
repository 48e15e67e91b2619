// SPDX-License-Identifier: MIT
// A bicubic polynomial Bezier patch in the power basis: the surface the error
// bounds (error_bound.h) evaluate millions of times, at about a third of the
// instructions of the Bernstein form (docs/results/tessellation.md). S(s, t) = o + sum_ij a_ij s^i
// t^j, i, j = 0..3, with o the control point (0, 0) (so the coefficients scale with the patch's
// extent, not with its coordinates' magnitude); each row sum_j a_ij t^j and then the sum over i by
// Horner's rule.
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
    // a and at are written in full by power_basis and not zeroed before (a
    // default-constructed one is a placeholder: the subdivision makes one per
    // subpatch, and zeroing it would cost as much as filling it).
    alignas(16) double a[3][4][4];
    // The t-derivative's coefficients of s^i t^j, j = 0..2: a[c][j + 1][i] (j + 1).
    alignas(16) double at[3][3][4];
    double error = 0; // bound on |computed point - S(s, t)| for s, t in [0, 1]
};

// Only for a polynomial bicubic patch (p = q = 3, every weight 1).
bool has_power_basis(const BezierPatch& b);
// rounding_bound false: `error` left 0 (for estimates, not proofs).
PowerBasisPatch power_basis(const BezierPatch& b, bool rounding_bound = true);

namespace power_lanes {

// Two lanes at a time (SSE2; GCC/Clang vector extension): the rows i = 0, 1
// and i = 2, 3 of the power basis. Each lane does the operations of the
// scalar form in its order, so the values (and the rounding bound) are those
// of the scalar Horner passes.
using Lanes = double __attribute__((vector_size(16)));

inline Lanes load(const double* p) {
    return *static_cast<const Lanes*>(__builtin_assume_aligned(p, 16));
}

// Rows (0, 1) and (2, 3) of coordinate c at t: sum_j a_ij t^j by Horner.
inline void rows(const PowerBasisPatch& pb, int c, Lanes T, Lanes row[2]) {
    const double(&a)[4][4] = pb.a[c];
    for (int h = 0; h < 2; ++h)
        row[h] = ((load(a[3] + 2 * h) * T + load(a[2] + 2 * h)) * T + load(a[1] + 2 * h)) * T +
                 load(a[0] + 2 * h);
}

} // namespace power_lanes

// Point and derivatives with respect to the local (s, t), s, t in [0, 1].
// Inline: the bounds' hot loops call them millions of times.
inline SurfacePoint evaluate(const PowerBasisPatch& pb, double s, double t) {
    using namespace power_lanes;
    const Lanes T = {t, t}, S = {s, s};
    double X[3], Xu[3], Xv[3];
    for (int c = 0; c < 3; ++c) {
        const double(&d)[3][4] = pb.at[c];
        Lanes row[2], rowv[2];
        rows(pb, c, T, row);
        for (int h = 0; h < 2; ++h)
            rowv[h] = (load(d[2] + 2 * h) * T + load(d[1] + 2 * h)) * T + load(d[0] + 2 * h);
        // (row_i, rowv_i): the point's and the t-derivative's Horner passes in s together.
        const Lanes r0 = __builtin_shufflevector(row[0], rowv[0], 0, 2);
        const Lanes r1 = __builtin_shufflevector(row[0], rowv[0], 1, 3);
        const Lanes r2 = __builtin_shufflevector(row[1], rowv[1], 0, 2);
        const Lanes r3 = __builtin_shufflevector(row[1], rowv[1], 1, 3);
        const Lanes xv = ((r3 * S + r2) * S + r1) * S + r0;
        X[c] = xv[0];
        Xv[c] = xv[1];
        Xu[c] = ((3 * r3[0]) * s + 2 * r2[0]) * s + r1[0];
    }
    return {pb.origin + Vec3{X[0], X[1], X[2]}, {Xu[0], Xu[1], Xu[2]}, {Xv[0], Xv[1], Xv[2]}};
}

// The point alone: the same value as evaluate(pb, s, t).point.
inline Vec3 evaluate_point(const PowerBasisPatch& pb, double s, double t) {
    using namespace power_lanes;
    const Lanes T = {t, t};
    double X[3];
    for (int c = 0; c < 3; ++c) {
        Lanes row[2];
        rows(pb, c, T, row);
        X[c] = ((row[1][1] * s + row[1][0]) * s + row[0][1]) * s + row[0][0];
    }
    return pb.origin + Vec3{X[0], X[1], X[2]};
}

} // namespace seamless
