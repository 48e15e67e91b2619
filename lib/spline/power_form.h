// SPDX-License-Identifier: MIT
// Power form of a Bezier patch (paper section 4): X(s, t) = sum_ij a_ij s^i t^j
// for each homogeneous coordinate (w x, w y, w z, w), local (s, t) in [0,1]^2.
// The coefficients are intervals computed with outward rounding from the
// Bernstein control points, so the interval power form ENCLOSES the exact patch;
// the same holds for the power forms of the partial derivatives.
#pragma once

#include <seamless/interval/interval.h>
#include <seamless/spline/bezier_patch.h>

#include <algorithm>

namespace seamless {

// Coefficients packed by the actual degrees: a(c, i, j) at (c (p + 1) + i) (q + 1) + j,
// so a bicubic's 4 x 4 x 4 coefficients are 1 KB, contiguous, in room for degree
// 9 (6.4 KB, never allocated). Set p, q and dim before writing coefficients.
// Nothing is zeroed and copies take only the coefficients in use: every
// producer writes exactly those of its degrees. (Zeroing and strided rows
// touched all 6.4 KB of each of a projected patch's 6 forms: project_scene of
// the teapot, 36 patches, 444 -> 320 page faults at ~11.5 us each.)
struct PowerForm {
    static constexpr int kMaxOrder = BezierPatch::kMaxOrder;
    static constexpr int kMaxDim = 4;
    static constexpr int kCapacity = kMaxDim * kMaxOrder * kMaxOrder;

    int p = 0, q = 0; // degrees in s and t (>= 0)
    int dim = 4;      // number of coordinates: 4 for (wx, wy, wz, w), fewer for derived systems

    PowerForm() {} // coefficients unset (not zeroed): see above
    // Copies the degrees and the dim (p + 1) (q + 1) coefficients in use only.
    PowerForm(const PowerForm& f) { *this = f; }
    PowerForm& operator=(const PowerForm& f) {
        if (this == &f) return *this;
        p = f.p;
        q = f.q;
        dim = f.dim;
        std::copy_n(f.a, f.size(), a);
        return *this;
    }

    // Number of coefficients in use.
    int size() const { return dim * (p + 1) * (q + 1); }
    Interval& at(int c, int i, int j) { return a[(c * (p + 1) + i) * (q + 1) + j]; }
    const Interval& at(int c, int i, int j) const { return a[(c * (p + 1) + i) * (q + 1) + j]; }

  private:
    union { // left unconstructed by PowerForm(): no zeroing
        Interval a[kCapacity];
    };
};

// Interval power form of the homogeneous coordinates of a patch.
PowerForm power_form(const BezierPatch& b);
// Power forms of d/ds and d/dt (degree lowered by one; a degree-0 direction gives 0).
PowerForm derivative_s(const PowerForm& f);
PowerForm derivative_t(const PowerForm& f);
// The same three into `out` (in place: no temporary form copied).
void power_form(const BezierPatch& b, PowerForm& out);
void derivative_s(const PowerForm& f, PowerForm& out);
void derivative_t(const PowerForm& f, PowerForm& out);
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
