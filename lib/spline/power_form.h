// SPDX-License-Identifier: MIT
// Power form of a Bezier patch (paper section 4): X(s, t) = sum_ij a_ij s^i t^j
// for each homogeneous coordinate (w x, w y, w z, w), local (s, t) in [0,1]^2.
// The coefficients are intervals computed with outward rounding from the
// Bernstein control points, so the interval power form ENCLOSES the exact patch;
// the same holds for the power forms of the partial derivatives.
#pragma once

#include <seamless/interval/interval.h>
#include <seamless/spline/bezier_patch.h>

#include <array>

namespace seamless {

struct PowerForm {
    static constexpr int kMaxOrder = BezierPatch::kMaxOrder;
    static constexpr int kMaxDim = 4;

    int p = 0, q = 0; // degrees in s and t (>= 0)
    int dim = 4;      // number of coordinates: 4 for (wx, wy, wz, w), fewer for derived systems
    std::array<Interval, kMaxDim * kMaxOrder * kMaxOrder> a{}; // a(c, i, j) of s^i t^j

    Interval& at(int c, int i, int j) { return a[(c * kMaxOrder + i) * kMaxOrder + j]; }
    const Interval& at(int c, int i, int j) const { return a[(c * kMaxOrder + i) * kMaxOrder + j]; }
};

// Interval power form of the homogeneous coordinates of a patch.
PowerForm power_form(const BezierPatch& b);
// Power forms of d/ds and d/dt (degree lowered by one; a degree-0 direction gives 0).
PowerForm derivative_s(const PowerForm& f);
PowerForm derivative_t(const PowerForm& f);
// Linear combination g_k = sum_c m[k][c] f_c, k < rows, of the coordinates of f
// (e.g. the ray equations e.X - (e.O) W of ray_patch.h). Coefficients are intervals.
PowerForm combine(const PowerForm& f, const Interval m[][PowerForm::kMaxDim], int rows);
// The same into `out`, writing only the coefficients of f's degrees: nothing
// zeroed or copied (out's other coefficients are never read for those degrees).
void combine(const PowerForm& f, const Interval m[][PowerForm::kMaxDim], int rows, PowerForm& out);

// Enclosure of coordinate c at a point (Horner, interval arithmetic).
Interval evaluate(const PowerForm& f, int c, double s, double t);
// Plain double evaluation at the coefficients' midpoints: for tests and quick estimates.
double evaluate_mid(const PowerForm& f, int c, double s, double t);

} // namespace seamless
