// SPDX-License-Identifier: MIT
// OpenCASCADE's surfaces as the model's B-spline surfaces: exactly where an
// exact NURBS form exists, approximated otherwise (step_iges.h). Internal to
// the STEP/IGES module (libseamless_step_iges.so): it exposes OpenCASCADE's
// types, which no other header of seamless does.
#pragma once

#include <seamless/spline/bspline_surface.h>

#include <Geom_BSplineSurface.hxx>
#include <Geom_Surface.hxx>

#include <string>

namespace seamless::step_iges {

// "B-spline", "plane", ...: what the file's surface is, for messages and `info`.
std::string kind_of(const Handle(Geom_Surface) & s);

struct Converted {
    Handle(Geom_BSplineSurface) surface; // null: no conversion found
    bool exact = true;
    double error = 0; // approximated: OpenCASCADE's largest distance, model units
};

// The part [u1, u2] x [v1, v2] of `s` as a non-periodic B-spline surface of
// degree at most kMaxDegree: exact where possible, else approximated within
// `rel_tol` times its bounding box diagonal or `abs_tol`, the larger.
Converted convert(const Handle(Geom_Surface) & s, double u1, double u2, double v1, double v2,
                  double rel_tol, double abs_tol = 0);

// The approximation `convert` falls back on, over the same parameters as
// `s` (GeomConvert_ApproxSurface approximates (u, v) -> s(u, v)).
Converted approximate(const Handle(Geom_Surface) & s, double u1, double u2, double v1, double v2,
                      double rel_tol, double abs_tol = 0);

// The model's surface of b, named `name`.
BSplineSurface to_model(const Handle(Geom_BSplineSurface) & b, const std::string& name);

} // namespace seamless::step_iges
