// SPDX-License-Identifier: MIT
// B-spline curve of any degree 1..kMaxDegree, polynomial or rational: the 3D
// curves of B-rep edges and the pcurves (curves in a surface's (u,v) domain)
// of the faces that use them (model/brep.h). A pcurve keeps (u, v, 0).
#pragma once

#include <seamless/base/vec.h>
#include <seamless/spline/bspline_surface.h>

#include <vector>

namespace seamless {

struct BSplineCurve {
    int degree = 1;
    std::vector<double> knots;   // size() + degree + 1 non-decreasing numbers
    std::vector<Vec3> points;    // control points; a pcurve's are (u, v, 0)
    std::vector<double> weights; // empty: polynomial; else one positive weight per point

    int size() const { return static_cast<int>(points.size()); }
    bool rational() const { return !weights.empty(); }
    double weight(int i) const { return weights.empty() ? 1.0 : weights[i]; }
    // Domain [knots[degree], knots[size()]]; knots need not be clamped.
    double t_min() const { return knots[degree]; }
    double t_max() const { return knots[size()]; }
};

// Point and first derivative.
struct CurvePoint {
    Vec3 point, tangent;
};

// The curve at t in its domain (values outside are clamped to it).
CurvePoint evaluate(const BSplineCurve& c, double t);
// The point alone (evaluate(c, t).point, to the bit), without the derivative.
Vec3 evaluate_point(const BSplineCurve& c, double t);

} // namespace seamless
