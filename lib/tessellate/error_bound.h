// SPDX-License-Identifier: MIT
// Upper bound on the distance between a planar subpatch and its fan triangles
// (paper section 6; section 5 on the accuracy lost to triangles). The bound is
// parametric: with F the piecewise linear map of the subpatch's parameter
// square onto its triangles (centre (1/2,1/2), boundary vertices at their
// parameters), sup |S(s,t) - F(s,t)| bounds the two-way (Hausdorff) distance
// between the subpatch S and the union of its triangles. It is split as
//   |S - F| <= |S - B_C| + |B_C - B_V| + |B_V - F|
// with B_C, B_V the bilinear interpolants of the subpatch's corner control
// points C and of the mesh's corner vertices V (which may lie on a coarser
// neighbour's straight edge).
#pragma once

#include <seamless/spline/bezier_patch.h>

#include <array>
#include <span>

namespace seamless {

// sup |S - B_C| over the patch, B_C the bilinear interpolant of its corners.
// Polynomial: S - B_C is a Bezier patch with control points
// b_ij - B_C(i/p, j/q), so their largest norm bounds it (convex hull property).
// Rational: (X - W B_C) / W with X, W the homogeneous numerator and weight; the
// numerator is a degree (p+1, q+1) Bezier patch (Bernstein product), divided by
// the smallest weight, which bounds W from below.
double bilinear_deviation(const BezierPatch& b);

// A vertex of a subpatch's fan: local parameters on the subpatch and position.
struct FanVertex {
    double s = 0, t = 0;
    Vec3 position;
};

// sup |B_V - F| for the fan from `centre` (at (1/2,1/2)) over the closed
// boundary polygon `ring` (counterclockwise in (s,t), starting at corner
// (0,0); ring[0] is not repeated at the end). V: the positions at the corners
// (0,0), (1,0), (1,1), (0,1). On each fan triangle F is the linear interpolant
// of its vertices and B_V = L + twist * g with L linear and g the
// interpolation error of s*t, |g| <= sum_{k<l} l_k l_l |ds_kl dt_kl| <= max/3.
double fan_deviation(const std::array<Vec3, 4>& V, Vec3 centre, std::span<const FanVertex> ring);

// Allowance for rounding in de Casteljau (depth halvings) and evaluation at the
// coordinates' magnitude `scale`: a few ulps per operation.
double rounding_allowance(int depth, double scale);

} // namespace seamless
