// SPDX-License-Identifier: MIT
// Beyond an open side of a face's domain the surface is its tangent plane
// there (FaceSurface); a piece of a triangle there is bounded against the
// end patch's polynomial continuation P (triangle_bound.h), plus P's
// distance to that plane: (A h_u^2 + 2 B h_u h_v + C h_v^2) / 2 (Taylor at
// the side; h the overhang, A, B, C bounds of P's second derivatives over it).
#pragma once

#include <seamless/spline/bezier_patch.h>

#include <array>

namespace seamless {

// That distance for the piece with local corners st on `patch`, overhang
// hu, hv ((u,v) units); +infinity where a weight of the continuation is not
// positive.
double beyond_side(const BezierPatch& patch, const std::array<std::array<double, 2>, 3>& st,
                   double hu, double hv);

} // namespace seamless
