// SPDX-License-Identifier: MIT
// The surface point S(s, t) of a Bezier patch exactly as evaluate()
// (bezier_patch.h) computes it, without its derivatives, and the unit normal
// there, also at poles (its limit): the tessellation's vertices and subpatch
// centres are these points (section 6: the vertices lie on the surface), where
// evaluate()'s derivatives would be work for nothing.
#pragma once

#include <seamless/spline/fixed_degree.h>

namespace seamless {

// evaluate_fixed<P, Q, true>(b, s, t).point: the same operations in the same
// order (fixed_degree.h), so the same value bit for bit.
template <int P, int Q> Vec3 exact_point_fixed(const BezierPatch& b, double s, double t) {
    double Bu[P + 1], dBu[P + 1], Bv[Q + 1], dBv[Q + 1];
    bernstein_fixed<P>(s, Bu, dBu);
    bernstein_fixed<Q>(t, Bv, dBv);
    using Lanes = double __attribute__((vector_size(16)));
    Lanes X[2] = {};
    for (int i = 0; i <= P; ++i) {
        Lanes row[2] = {};
        for (int j = 0; j <= Q; ++j) {
            const HPoint& h = b.at(i, j);
            const Lanes c[2] = {{h.x, h.y}, {h.z, h.w}};
            for (int k = 0; k < 2; ++k) row[k] = row[k] + Bv[j] * c[k];
        }
        for (int k = 0; k < 2; ++k) X[k] = X[k] + Bu[i] * row[k];
    }
    return Vec3{X[0][0], X[0][1], X[1][0]} / X[1][1];
}

// evaluate(b, s, t).point, the same value bit for bit.
inline Vec3 exact_point(const BezierPatch& b, double s, double t) {
    if (b.p == b.q) {
        if (b.p == 3) return exact_point_fixed<3, 3>(b, s, t);
        if (b.p == 2) return exact_point_fixed<2, 2>(b, s, t);
        if (b.p == 1) return exact_point_fixed<1, 1>(b, s, t);
    }
    return evaluate(b, s, t).point;
}

// Unit normal dP/du x dP/dv at local (s, t) of `b`; where it vanishes (a pole,
// a collapsed edge) the limit normal, approached from (toward_s, toward_t).
Vec3 unit_normal(const BezierPatch& b, double s, double t, double toward_s, double toward_t);
// Where the normal does not vanish at (s, t) itself, nor is one derivative
// a rounding of the other (a pole whose control points differ by rounding):
// true, and in n the same value as unit_normal's (then a function of b, s
// and t alone); else false.
bool regular_unit_normal(const BezierPatch& b, double s, double t, Vec3& n);

} // namespace seamless
