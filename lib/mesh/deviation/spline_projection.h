// SPDX-License-Identifier: MIT
// The closest point of a B-spline surface or curve to a point, by damped
// Gauss-Newton from a starting parameter (a local minimum of the distance:
// the deviation measures seed it from a nearby sample).
#pragma once

#include <seamless/spline/bspline_curve.h>
#include <seamless/spline/bspline_surface.h>

namespace seamless {

struct SurfaceProjection {
    double distance = 0; // |S(u, v) - x|, the smallest reached
    double u = 0, v = 0;
};

// From (u, v), clamped to the surface's domain throughout.
SurfaceProjection project_to_surface(const BSplineSurface& s, Vec3 x, double u, double v,
                                     int iterations);

struct CurveProjection {
    double distance = 0; // |C(t) - x|, the smallest reached
    double t = 0;
};

// From t, clamped to [t0, t1] (an edge's range of its curve) throughout.
CurveProjection project_to_curve(const BSplineCurve& c, Vec3 x, double t, double t0, double t1,
                                 int iterations);

} // namespace seamless
