// SPDX-License-Identifier: MIT
// The parameter rectangle of a STEP/IGES face and whether the face is that
// whole rectangle (untrimmed). Internal to the STEP/IGES module
// (libseamless_step_iges.so): it exposes OpenCASCADE's types.
#pragma once

#include <Geom_Surface.hxx>
#include <TopoDS_Face.hxx>

namespace seamless::step_iges {

// The parameter rectangle a face covers and whether it is bounded by exactly
// that rectangle (its natural boundary): one wire, every pcurve on the
// rectangle's sides, and in each direction where the surface is bounded (not
// periodic, not infinite) the rectangle reaching the surface's bounds, all
// within the boundary's tolerance. The rectangle is snapped to the bounds in
// those directions, so an untrimmed B-spline face is its whole surface.
struct FaceRange {
    double u1, u2, v1, v2;
    bool natural;
};

FaceRange face_range(const TopoDS_Face& face, const Handle(Geom_Surface) & s);

} // namespace seamless::step_iges
