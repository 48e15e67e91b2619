// SPDX-License-Identifier: MIT
// A tensor-product Bezier patch restricted to a triangle of its parameter
// plane is a triangular Bezier patch of total degree n = p + q; its Bernstein
// coefficients over the triangle (corners y_0, y_1, y_2) come from the
// blossom (paper section 4: ranges of a patch over smaller parameter sets
// from its recomputed control points, by the convex hull property). The
// total-degree blossom of a polynomial of bidegree (p, q) is the mean of its
// tensor-product blossom f(u_1..u_p; v_1..v_q) over the ways of sending p of
// the n arguments to the u slots (it is symmetric, affine in each argument
// and equals the polynomial on the diagonal), so
//   b_ijk = sum_{a+b+c=p} C(i,a) C(j,b) C(k,c) / C(n,p)
//             f(s_0^a s_1^b s_2^c; t_0^(i-a) t_1^(j-b) t_2^(k-c)),
// computed by de Casteljau's algorithm: the patch over the corners' (s, t)
// bounding box, then in each direction one pyramid at the third corner's
// place between the other two (the .cpp). Homogeneous coordinates, so a
// rational patch is the quotient of two such polynomials.
#pragma once

#include <seamless/spline/bezier_patch.h>

#include <array>

namespace seamless {

// Triangular Bernstein coefficients of degree n: b_ijk, k = n - i - j.
struct TriangularNet {
    static constexpr int kMaxOrder = 2 * kMaxDegree + 2; // degree n + 1 after elevation
    int n = 0;
    std::array<HPoint, kMaxOrder*(kMaxOrder + 1) / 2> b{};
    // Every homogeneous coordinate of every coefficient is within this of
    // the exact one over a triangle whose corners are within 16 u max |s|,
    // |t| of the given ones (u = 2^-53; the split parameters are rounded),
    // from de Casteljau's and the sums' rounding (the .cpp).
    double error = 0;

    static int index(int n, int i, int j) { return i * (2 * n + 3 - i) / 2 + j; }
    HPoint& at(int i, int j) { return b[index(n, i, j)]; }
    const HPoint& at(int i, int j) const { return b[index(n, i, j)]; }
};

// The coefficients of `patch` over the triangle with local corners st (any
// points of the plane: outside [0,1]^2 the patch's polynomial continuation).
void restrict_to_triangle(const BezierPatch& patch, const std::array<std::array<double, 2>, 3>& st,
                          TriangularNet& out);

// The same in two stages, for a caller that may stop after the first: the
// patch over the bounding box [s_lo, s_hi] x [t_lo, t_hi] of the corners
// (tensor-product coefficients of bidegree (p, q)), then from it the
// triangle's.
struct BoxNet {
    static constexpr int K = BezierPatch::kMaxOrder;
    int p = 0, q = 0;
    std::array<double, 3> s{}, t{}; // the triangle's local corners
    double s_lo = 0, s_hi = 0, t_lo = 0, t_hi = 0;
    std::array<HPoint, K * K> b; // (i, j) at i * K + j
    // As TriangularNet::error, for b over a box whose corners are within 16
    // u max |s|, |t| of the given ones.
    double error = 0;
    double M = 0, grow = 1; // the rounding's scale (the .cpp)
    const HPoint& at(int i, int j) const { return b[i * K + j]; }
};
void restrict_to_box(const BezierPatch& patch, const std::array<std::array<double, 2>, 3>& st,
                     BoxNet& out);
void box_to_triangle(const BoxNet& box, TriangularNet& out);

} // namespace seamless
