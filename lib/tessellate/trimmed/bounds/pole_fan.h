// SPDX-License-Identifier: MIT
// Triangles at a pole or apex, certified geometrically. Where a side of the
// (u,v) domain collapses to one point (a degenerate edge: all of it is one
// mesh vertex P), the triangles with a corner x_a on that side (to a
// rounding of the domain's extent) are wide in u and S(x) drifts along the
// ring away from L(x): the parametric bound of triangle_bound.h counts that
// drift. Such a triangle (x_a, y_l, y_r), y_l before y_r along the side, is
// paired instead with the trapezoid Z between the side and its far edge
// y_l y_r with vertical ends: the rectangle [y_l, y_r] x [side, nearer y] by the map
// bilinear over it (P along the side, the mesh edges P Q_l and P Q_r on its
// ends: every point at its own height on the ring, no drift;
// TriangleBound::bilinear_box), and the triangle left above it affinely.
// Two trapezoids that share an end pair it with the same mesh edge
// linearly, and the side goes to P, so the pairing is continuous and onto
// the fan's mesh triangles. It covers the face's part next to the side when
// the fan is one monotone strip: the y intervals follow each other exactly
// and the points of the side's edges span exactly the first y to the last
// (so the fan's region, its kept triangles and the ones with two corners on
// the side that the mesh drops, ends in vertical edges: a seam or a
// meridian); then the trapezoids tile that region. Otherwise the fan's
// triangles keep the parametric bound.
#pragma once

#include <seamless/tessellate/trimmed/bounds/triangle_bound.h>

#include <span>
#include <vector>

namespace seamless {

struct RunTriangle {
    std::array<UV, 3> uv;
    std::array<Vec3, 3> Q;
    std::array<int, 3> id; // mesh vertex ids
};

// The largest bound over the run's triangles that belong to pole fans
// certified as above (handled[k] set for them; 0 when none). `side_points`:
// the (u,v) points of the degenerate edges of the faces on this surface.
double pole_fan_bounds(const TriangleBound& bound, const BSplineSurface& s,
                       std::span<const RunTriangle> run, std::span<const UV> side_points,
                       std::vector<char>& handled);

} // namespace seamless
