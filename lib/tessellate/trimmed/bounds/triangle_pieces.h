// SPDX-License-Identifier: MIT
// A (u,v) triangle cut along lines u = const and v = const (knot lines, a
// domain's ends and their periodic copies) into triangles that each lie in
// one cell between consecutive lines, so that a surface is one polynomial
// (one Bezier patch) on each. The cut runs in the triangle's barycentric
// coordinates lambda: every corner of a piece carries its lambda and its
// (u,v) point, and the pieces cover the triangle's lambda simplex (up to
// the roundings of the cut points: a few ulps). A triangle of no area in
// (u,v) is cut the same way.
#pragma once

#include <array>
#include <span>
#include <vector>

namespace seamless {

using UV = std::array<double, 2>;

struct PieceCorner {
    std::array<double, 3> lambda; // barycentric in the cut triangle
    UV uv;
};

struct TrianglePiece {
    std::array<PieceCorner, 3> corner;
    // The cell: between cuts_u[cell_u - 1] and cuts_u[cell_u] (the
    // triangle's own extent beyond the first and last cut), v alike.
    int cell_u = 0, cell_v = 0;
};

// Cuts the triangle with corners uv at the increasing values cuts_u (in u)
// and cuts_v (in v), each strictly inside the triangle's extent; appends the
// pieces to `out`.
void cut_triangle(const std::array<UV, 3>& uv, std::span<const double> cuts_u,
                  std::span<const double> cuts_v, std::vector<TrianglePiece>& out);

} // namespace seamless
