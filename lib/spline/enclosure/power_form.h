// SPDX-License-Identifier: MIT
// Power form of a Bezier patch (paper section 4): X(s, t) = sum_ij a_ij s^i t^j
// for each homogeneous coordinate (w x, w y, w z, w), local (s, t) in [0,1]^2.
// The coefficients are intervals computed with outward rounding from the
// Bernstein control points, so the interval power form ENCLOSES the exact patch;
// the same holds for the power forms of the partial derivatives.
#pragma once

#include <seamless/base/check.h>
#include <seamless/base/raw_array.h>
#include <seamless/interval/interval.h>
#include <seamless/spline/bezier_patch.h>

#include <algorithm>
#include <utility>

namespace seamless {

// Coefficients packed by the actual degrees: a(c, i, j) at (c (p + 1) + i) (q + 1) + j.
// Room inside for a bicubic's 4 x 4 x 4 (1 KB); a form of higher degrees
// takes room for degree 9 (6.4 KB) on the heap once, kept for reuse (room for
// degree 9 inside would spread a patch's six forms over as many pages, each
// touched: docs/results/render.md). Set the degrees with set_degrees() before
// writing coefficients: it makes the room.
// Nothing is zeroed and copies take only the coefficients in use: every
// producer writes exactly those of its degrees.
struct PowerForm {
    static constexpr int kMaxOrder = BezierPatch::kMaxOrder;
    static constexpr int kMaxDim = 4;
    static constexpr int kCapacity = kMaxDim * kMaxOrder * kMaxOrder;
    static constexpr int kInline = kMaxDim * 4 * 4;

    // Degrees in s and t (>= 0) and the number of coordinates: 4 for (wx, wy,
    // wz, w), fewer for derived systems. Read here; written by set_degrees.
    int p = 0, q = 0;
    int dim = 4;

    PowerForm() : a_(inline_) {} // coefficients unset (not zeroed): see above
    // Copies the degrees and the dim (p + 1) (q + 1) coefficients in use only.
    PowerForm(const PowerForm& f) : a_(inline_) { *this = f; }
    PowerForm& operator=(const PowerForm& f) {
        if (this == &f) return *this;
        set_degrees(f.p, f.q, f.dim);
        std::copy_n(f.a_, f.size(), a_);
        return *this;
    }
    PowerForm(PowerForm&& f) noexcept : a_(inline_) { *this = std::move(f); }
    PowerForm& operator=(PowerForm&& f) noexcept {
        if (this == &f) return *this;
        if (f.heap_) { // take f's room; f keeps its own inside
            heap_ = std::move(f.heap_);
            a_ = heap_.get();
            f.a_ = f.inline_;
            p = f.p;
            q = f.q;
            dim = f.dim;
            return *this;
        }
        return *this = static_cast<const PowerForm&>(f);
    }

    // Sets the degrees and the dim, with room for their coefficients (their
    // values unset).
    void set_degrees(int p_, int q_, int dim_) {
        SEAMLESS_CHECK(p_ >= 0 && p_ < kMaxOrder && q_ >= 0 && q_ < kMaxOrder && dim_ >= 1 &&
                           dim_ <= kMaxDim,
                       "degrees and dim within the room for degree 9");
        if (!heap_ && dim_ * (p_ + 1) * (q_ + 1) > kInline) {
            heap_ = raw_array<Interval>(kCapacity);
            a_ = heap_.get();
        }
        p = p_;
        q = q_;
        dim = dim_;
    }
    // Number of coefficients in use.
    int size() const { return dim * (p + 1) * (q + 1); }
    Interval& at(int c, int i, int j) { return a_[(c * (p + 1) + i) * (q + 1) + j]; }
    const Interval& at(int c, int i, int j) const { return a_[(c * (p + 1) + i) * (q + 1) + j]; }

  private:
    Interval* a_;             // inline_ or heap_
    RawArray<Interval> heap_; // room for degree 9, when the degrees need it
    union {                   // left unconstructed by PowerForm(): no zeroing
        Interval inline_[kInline];
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
