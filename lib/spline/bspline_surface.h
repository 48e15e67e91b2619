// SPDX-License-Identifier: MIT
// Tensor-product B-spline surface (paper Definition 9), any degree 1..9 in u and v,
// polynomial or rational (NURBS, positive weights).
#pragma once

#include <seamless/base/vec.h>

#include <string>
#include <vector>

namespace seamless {

inline constexpr int kMaxDegree = 9;

struct BSplineSurface {
    std::string name;
    int degree_u = 3, degree_v = 3; // p, q
    int size_u = 4, size_v = 4;     // nu, nv: control net is nu x nv
    std::vector<double> knots_u;    // nu + p + 1 non-decreasing numbers
    std::vector<double> knots_v;    // nv + q + 1 non-decreasing numbers
    std::vector<Vec3> points;       // nu * nv; point (i, j) at index i * nv + j
    std::vector<double> weights;    // empty: polynomial; else nu * nv positive weights

    bool rational() const { return !weights.empty(); }
    Vec3 point(int i, int j) const { return points[static_cast<size_t>(i) * size_v + j]; }
    double weight(int i, int j) const {
        return weights.empty() ? 1.0 : weights[static_cast<size_t>(i) * size_v + j];
    }
    HPoint hpoint(int i, int j) const { return HPoint::from(point(i, j), weight(i, j)); }
    // Domain [knots_u[p], knots_u[nu]] x [knots_v[q], knots_v[nv]]; knots need not be clamped.
    double u_min() const { return knots_u[degree_u]; }
    double u_max() const { return knots_u[size_u]; }
    double v_min() const { return knots_v[degree_v]; }
    double v_max() const { return knots_v[size_v]; }
};

// Point, first partial derivatives and (unnormalised) normal dP/du x dP/dv.
struct SurfacePoint {
    Vec3 point, du, dv;
    Vec3 normal() const { return cross(du, dv); }
};

// Index k in [p, n-1] of the knot span [t_k, t_k+1) holding t (the last
// non-empty span for t at the domain's upper end).
int find_span(int degree, int n, const std::vector<double>& knots, double t);

// Values and first derivatives of the degree+1 B-splines non-zero on span k at t
// (de Boor / Cox recurrence). N0[r], N1[r] belong to basis function k - degree + r.
void basis_functions(int degree, int span, const std::vector<double>& knots, double t, double* N0,
                     double* N1);

// Evaluates the surface at (u, v) in its domain (values outside are clamped to it).
SurfacePoint evaluate(const BSplineSurface& s, double u, double v);
// The point alone (evaluate(s, u, v).point, to the bit), without derivatives.
Vec3 evaluate_point(const BSplineSurface& s, double u, double v);

// Bounding box of the control points: by the convex hull property it holds the surface.
Box3 control_box(const BSplineSurface& s);

} // namespace seamless
