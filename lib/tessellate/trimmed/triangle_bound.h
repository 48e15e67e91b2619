// SPDX-License-Identifier: MIT
// A certified bound on how far a triangle of a trimmed face lies from its
// surface: the two-way counterpart, for triangles in parameter space, of the
// subpatch bound of the Bezier pipeline (bounds/error_bound.h; paper section 6
// on the accuracy of triangles).
//
// For a (u,v) triangle T with corners x_k and mesh corners Q_k, the mesh is
// L(x) = sum lambda_k(x) Q_k. Taylor's theorem along x -> x_k gives
//   S(x) - L(x) = -sum lambda_k R_k + sum lambda_k (S(x_k) - Q_k),
//   |R_k| <= M |x_k - x|^2 / 2 + J |x_k - x|,
// with M a bound of |D^2 S[d, d]| over T (unit d; from the differenced
// control nets of the Bezier patches T's box meets, net_bounds.h) and J the
// sum of the jumps of the first derivative across the knot lines inside T's
// box where the basis is only C0 (a rational circle's double knots: the
// jump is zero up to rounding, but it is bounded, not assumed). Since
// sum lambda_k |x_k - x|^2 = R^2 - |x - c|^2 (c, R the circumcircle), its
// largest value over T is R^2 for an acute triangle and at most l^2 / 4 (l
// the longest side) otherwise. So over T
//   |S(x) - L(x)| <= M rho^2 / 2 + J rho + max_k |S(x_k) - Q_k|,
// in any affine scaling of (u,v), of which the tightest of a few is taken.
// Every point of the face covered by T is within this of its mesh point and
// back: a bound both ways for the part of the face the triangles cover.
#pragma once

#include <seamless/spline/bezier_patch.h>
#include <seamless/spline/bspline_surface.h>

#include <array>
#include <vector>

namespace seamless {

using UV = std::array<double, 2>;

class TriangleBound {
  public:
    explicit TriangleBound(const BSplineSurface& s);

    // The bound for the triangle with (u,v) corners uv and mesh corners Q;
    // +infinity where it cannot be certified (a discontinuous surface, a
    // corner outside the surface's domain).
    double operator()(const std::array<UV, 3>& uv, const std::array<Vec3, 3>& Q) const;

  private:
    struct Breaks {
        std::vector<double> at;   // distinct knots of the domain, increasing
        std::vector<double> jump; // per interior break: bound of the derivative's jump
    };
    // Bounds of |S_uu|, |S_uv|, |S_vv| over the box, in (u,v) units.
    std::array<double, 3> second_derivatives(double u0, double u1, double v0, double v1) const;
    double jumps_inside(const Breaks& b, double lo, double hi) const;
    void find_jumps(const BSplineSurface& s);

    std::vector<BezierPatch> patches_; // bezier_patches order: u spans outer, v spans inner
    Breaks u_, v_;
    double magnitude_ = 0; // largest control point coordinate, for rounding allowances
    const BSplineSurface& surface_;
};

} // namespace seamless
