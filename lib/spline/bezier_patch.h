// SPDX-License-Identifier: MIT
// Bezier patch (paper section 4): the pieces a B-spline surface falls into after
// knot insertion. Control points are homogeneous (w*x, w*y, w*z, w) so that
// de Casteljau subdivision is linear also for rational patches. Fixed-size
// storage: splitting and copying never allocate.
#pragma once

#include <seamless/base/vec.h>
#include <seamless/interval/interval.h>
#include <seamless/spline/bspline_surface.h>

#include <array>

namespace seamless {

struct BezierPatch {
    static constexpr int kMaxOrder = kMaxDegree + 1;

    int p = 3, q = 3;      // degrees in u and v
    bool rational = false; // some weight differs from 1
    int surface = -1;      // index of the source B-spline surface in its model
    double u0 = 0, u1 = 1; // parameter rectangle on the source surface
    double v0 = 0, v1 = 1;
    std::array<HPoint, kMaxOrder * kMaxOrder> cp{}; // (i, j) at i * kMaxOrder + j

    HPoint& at(int i, int j) { return cp[i * kMaxOrder + j]; }
    const HPoint& at(int i, int j) const { return cp[i * kMaxOrder + j]; }
    Vec3 point(int i, int j) const { return at(i, j).point(); }
    // Corner points P(0,0), P(1,0), P(1,1), P(0,1) in local (s, t).
    Vec3 corner(int c) const {
        switch (c) {
        case 0:
            return point(0, 0);
        case 1:
            return point(p, 0);
        case 2:
            return point(p, q);
        default:
            return point(0, q);
        }
    }
    // Source-surface parameters of local (s, t) in [0,1]^2.
    double u_at(double s) const { return u0 + s * (u1 - u0); }
    double v_at(double t) const { return v0 + t * (v1 - v0); }
};

// Bernstein values B_i^n(s) and derivatives d/ds B_i^n(s), i = 0..n
// (n <= kMaxDegree).
void bernstein(int n, double s, double* B, double* dB);

// Point, derivatives with respect to the LOCAL parameters (s, t) in [0,1]^2, and
// normal. Multiply du by 1/(u1-u0) for derivatives on the source surface.
SurfacePoint evaluate(const BezierPatch& b, double s, double t);
// The point alone (no derivatives, so cheaper than evaluate()); may differ
// from evaluate().point in the last bits. For estimates, not proofs.
Vec3 evaluate_point(const BezierPatch& b, double s, double t);
// Homogeneous point X(s,t) = sum B_i(s) B_j(t) cp_ij.
HPoint evaluate_homogeneous(const BezierPatch& b, double s, double t);

// Enclosures of the homogeneous coordinates 0..dims-1 of X(s, t), s, t in
// [0, 1], by de Casteljau's algorithm in doubles with a proven error bound:
// each level is a convex combination (1 - t) a + t b whose computed value is
// within 3.1u ((1 - t)|a| + t|b|) <= 3.1u M of the exact one (u = 2^-53, M =
// max |b_ij| of the coordinate; fl(1 - t) is exact or within u (1 - t)), and
// earlier errors pass through with convex weights, so after p + q levels the
// error is below 4u (p + q) M, plus underflow_allowance(3 (p + q)) for underflow. Far
// cheaper than interval Horner on the power form at a point.
void enclose_homogeneous(const BezierPatch& b, double s, double t, int dims, Interval* out);
// The same enclosures, and the point with its partial derivatives at (s, t)
// in doubles into frame (as evaluate() gives them, up to rounding: from the
// same de Casteljau levels for equal degrees 1 to 3, else evaluate()'s).
void enclose_homogeneous(const BezierPatch& b, double s, double t, int dims, Interval* out,
                         SurfacePoint& frame);
// The same by the loops for any degree (enclose_homogeneous takes
// enclose_homogeneous_fixed of fixed_degree.h for equal degrees 1 to 3: the same values).
void enclose_homogeneous_any_degree(const BezierPatch& b, double s, double t, int dims,
                                    Interval* out);

// A parameter direction of a patch: u (local s, the first index of cp) or v
// (local t, the second).
enum class Direction { u, v };

// De Casteljau subdivision along d at local parameter x (s for u, t for v);
// the halves keep the source surface and their part of the parameter rectangle.
void split(const BezierPatch& b, Direction d, double x, BezierPatch& lo, BezierPatch& hi);
inline void split_u(const BezierPatch& b, double s, BezierPatch& lo, BezierPatch& hi) {
    split(b, Direction::u, s, lo, hi);
}
inline void split_v(const BezierPatch& b, double t, BezierPatch& lo, BezierPatch& hi) {
    split(b, Direction::v, t, lo, hi);
}

// Bounding box of the (projected) control points: holds the patch (convex hull property).
Box3 control_box(const BezierPatch& b);

} // namespace seamless
