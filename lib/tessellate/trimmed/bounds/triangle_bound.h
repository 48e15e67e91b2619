// SPDX-License-Identifier: MIT
// A certified bound on how far a triangle of a trimmed face lies from its
// surface: the two-way counterpart, for triangles in parameter space, of the
// subpatch bound of the Bezier pipeline (bounds/error_bound.h; paper section 6
// on the accuracy of triangles), from the control points of the surface
// restricted to the triangle (paper section 4: the convex hull property on
// recomputed control points).
//
// For a (u,v) triangle T with corners x_k and mesh corners Q_k, the mesh is
// L(lambda) = sum lambda_k Q_k over T's barycentric coordinates lambda.
// T is cut along the knot lines into pieces on each of which the surface is
// one rational polynomial X / W (triangle_pieces.h); on a piece with
// corners y_j, where L takes the values L_j, the surface is a triangular
// Bezier patch of degree n = p + q (triangle_restriction.h), and
//   E = X - W L = sum_a e_a B_a,  W = sum_a w_a B_a
// in the Bernstein basis of degree n + 1 (W L has that degree). With every
// w_a > 0, S - L = E / W is a convex combination of the e_a / w_a, so
//   |S(y) - L(y)| <= max_a |e_a| / w_a
// at every point of the piece: every point of the face covered by T is
// within this of its mesh point and back (two ways), with no quotient rule
// and no separate term for the corners or for C0 knot lines, which the cut
// follows. e_a / w_a is a weighted mean of the control points' distances to
// points of the flat triangle; as T shrinks it tends to the parametric
// interpolation error, to within a factor (n + 1) / n.
//
// The face's surface is FaceSurface's: a closed direction is periodic (a
// piece beyond the domain is its copy shifted by whole periods), and beyond
// an open side the surface is its tangent plane there. There the pieces are
// bounded against the end patch's polynomial continuation P, plus the
// distance from P to the tangent plane, (A h_u^2 + 2 B h_u h_v + C h_v^2) / 2
// (Taylor at the side; h the overhang, A, B, C bounds of P's second
// derivatives over it): a pcurve a tolerance past the domain adds a term of
// the order of that tolerance squared.
#pragma once

#include <seamless/spline/bezier_patch.h>
#include <seamless/spline/bspline_surface.h>
#include <seamless/tessellate/trimmed/bounds/triangle_pieces.h>

#include <array>
#include <vector>

namespace seamless {

class TriangleBound {
  public:
    // closed_u, closed_v: the surface is periodic in that direction
    // (FaceSurface::closed_u).
    explicit TriangleBound(const BSplineSurface& s, bool closed_u = false, bool closed_v = false);

    // The bound for the triangle with (u,v) corners uv and mesh corners Q;
    // +infinity where it cannot be certified (a weight not positive on the
    // continuation beyond an open side). For a caller that keeps the largest
    // bound (brep_certification.h), `cutoff`: where a piece's hull before
    // the full degree elevation (hull_bound in the .cpp) already keeps the
    // triangle's bound at most cutoff, that looser one stands, still a
    // bound and still at most cutoff; elsewhere the bound is the full one.
    double operator()(const std::array<UV, 3>& uv, const std::array<Vec3, 3>& Q,
                      double cutoff = 0) const;

    // The bound over the (u,v) rectangle box = {u0, u1, v0, v1} inside the
    // domain, for the map onto the mesh bilinear over it with the values M
    // at (u0, v0), (u1, v0), (u1, v1), (u0, v1): the same hull, of the
    // tensor-product coefficients of E = X - W M (bilinear_box.cpp; a pole
    // fan's pairing, pole_fan.h). +infinity where it cannot be certified.
    double bilinear_box(const std::array<double, 4>& box, const std::array<Vec3, 4>& M) const;

    // A bound of |S_u| and |S_v| over the domain (model units per (u,v) unit).
    double max_gradient() const;

  private:
    struct Axis {
        std::vector<double> at; // distinct knots of the domain, increasing
        bool closed = false;
        double lo() const { return at.front(); }
        double hi() const { return at.back(); }
    };
    // The span of x (after whole periods `shift` are taken off, closed axes).
    int span_of(const Axis& a, double x, double& shift) const;
    void cuts(const Axis& a, double lo, double hi, std::vector<double>& out) const;
    // The bound over one piece, on `patch` shifted by whole periods.
    double piece_bound(const TrianglePiece& piece, const BezierPatch& patch, double shift_u,
                       double shift_v, const std::array<Vec3, 3>& Q, double cutoff) const;

    std::vector<BezierPatch> patches_; // bezier_patches order: u spans outer, v spans inner
    std::vector<double> gradient_;     // per patch: a bound of |S_u|, |S_v| (rounding terms)
    Axis u_, v_;
};

} // namespace seamless
