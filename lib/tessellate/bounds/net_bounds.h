// SPDX-License-Identifier: MIT
// Bounds on a patch's second derivatives from its differenced control net
// (the Taylor remainders of the fan bounds, error_bound.h; paper section 6 on
// the accuracy of triangles): the net of S - c is built once and measured
// along as many directions as a bound needs.
#pragma once

#include <seamless/spline/bezier_patch.h>

#include <array>

namespace seamless {

// Bounds over [0,1]^2 of S' = S - c and its first and second partial
// derivatives, measured by a magnitude (the Euclidean norm, or |n . v| for a
// unit n).
// X' = X - W c is the homogeneous form of S'; its derivatives' Bernstein
// coefficients are differences of the control net, bounded by their largest
// magnitude (convex hull property); the quotient rule with W >= wlo > 0 gives
//   S_s  = (X'_s - S' W_s) / W,
//   S_ss = (X'_ss - 2 S_s W_s - S' W_ss) / W,
//   S_st = (X'_st - S_s W_t - S_t W_s - S' W_st) / W.
struct DerivativeBounds {
    double A = 0, B = 0, C = 0; // |S_ss|, |S_st|, |S_tt|
};

// The differenced control net of S' = S - c, computed once and measured along
// as many directions as a bound needs (split_bounds: one per fan triangle).
// Index groups (dx, dy, dz): the points P - c, then the first, second and mixed
// differences of X' in s and t (their Bernstein coefficients up to the factors
// p, p (p - 1), ...). The weights' differences are direction-free: kept as
// their largest magnitudes, times those factors.
struct Net {
    static constexpr int kN = BezierPatch::kMaxOrder * BezierPatch::kMaxOrder;
    enum Group { kP0, kXs, kXt, kXss, kXst, kXtt, kGroups };
    int p = 0, q = 0;
    // Raw doubles, one array per coordinate (split_bounds takes two at a
    // time): only the first count[g] of each group are written and read (a
    // Vec3 array would be zeroed on every construction, 14 KB).
    alignas(16) std::array<double, kGroups * kN> dx, dy, dz;
    std::array<int, kGroups> count{};
    double Ws = 0, Wt = 0, Wss = 0, Wst = 0, Wtt = 0;
    double wlo = 1;
    void add(Group g, Vec3 v) {
        const int i = g * kN + count[g]++;
        dx[i] = v.x, dy[i] = v.y, dz[i] = v.z;
    }
    Vec3 at(int g, int i) const { return {dx[g * kN + i], dy[g * kN + i], dz[g * kN + i]}; }
};

// The net of S - c over b's local [0,1]^2 (a bicubic patch as a 4 x 4 net:
// the same values, the loops fixed).
Net net_of(const BezierPatch& b, Vec3 c);
// The net of S - c over the box [s0, s1] x [t0, t1] of `patch`'s local
// parameters: extract_box (error_bound.h), for a bicubic patch on its 4 x 4
// net alone (the same operations, so the same points).
Net box_net(const BezierPatch& patch, double s0, double s1, double t0, double t1, Vec3 c);

// Bounds of S itself (Euclidean norm).
DerivativeBounds derivative_bounds(const Net& n);

// The Taylor remainder over parameter extents ds x dt: the largest distance
// between S and its linear interpolant on a triangle of those extents.
inline double taylor_remainder(const DerivativeBounds& d, double ds, double dt) {
    return (d.A * ds * ds + 2 * d.B * ds * dt + d.C * dt * dt) / 8;
}

// The derivative bounds of n . S and of the tangential part S - (n . S) n, for
// a unit n (the zero vector: both the full bounds). Both parts are linear maps
// of S, so their remainders bound the two components of g separately; the
// tangential part holds only the parametrisation's drift and the tilt between
// n and the surface normal, far less than |S_ss| where the surface curves.
struct SplitBounds {
    DerivativeBounds normal, tangential;
};

SplitBounds split_bounds(const Net& net, Vec3 n);

} // namespace seamless
