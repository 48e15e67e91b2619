// SPDX-License-Identifier: MIT
// OpenCASCADE's edge curves and pcurves as the B-rep's B-spline curves
// (model/brep.h), keeping their parametrisation: an edge's 3D curve and its
// pcurves share the edge's parameter ("same parameter"), so a conversion that
// reparametrised one of them (a conic's exact rational form) would break the
// other. Internal to the STEP/IGES module (libseamless_step_iges.so): it
// exposes OpenCASCADE's types.
#pragma once

#include <seamless/spline/bspline_curve.h>

#include <Geom2d_Curve.hxx>
#include <Geom_Curve.hxx>

namespace seamless::step_iges {

struct ConvertedCurve {
    BSplineCurve curve; // non-periodic, degree <= kMaxDegree, domain holding [f, l]
    bool ok = false;    // false: no conversion found
    double error = 0;   // approximated: OpenCASCADE's largest distance (model units)
};

// c over [f, l], with the same parameter t: exactly for lines, Bezier and
// B-spline curves (the forms BRepBuilderAPI_NurbsConvert leaves), else (a
// conic left over, degree above kMaxDegree) approximated within `tol` as a
// function of t.
ConvertedCurve convert_curve(const Handle(Geom_Curve) & c, double f, double l, double tol);
// The same for a pcurve; its points are (u, v, 0).
ConvertedCurve convert_pcurve(const Handle(Geom2d_Curve) & c, double f, double l, double tol);

} // namespace seamless::step_iges
