// SPDX-License-Identifier: MIT
// A B-rep vertex stands for every point within its tolerance: the edges
// meeting there may end anywhere in that ball. An edge's polyline points
// inside the ball next to its end vertex are that vertex. Left in where the
// curve's end lies behind the vertex (pyocc_11752: 5.2e-7 behind it, within
// its tolerance of 1e-5, the curve split there for the angle), the polyline
// steps back from the vertex to the curve and turns forward again: it folds
// onto itself, and the triangles of both faces along it overlap.
#pragma once

#include <seamless/model/brep.h>
#include <seamless/tessellate/trimmed/edge_discretisation.h>

namespace seamless {

// Drops the interior points of `line` that lie, in a run from either end,
// within the tolerance of that end's vertex (at most a small fraction of
// the deviation D: a wide ball would cut the curve short by more than D).
// A closed edge keeps at least two interior points.
void drop_points_in_vertex_balls(const BRep& brep, int edge, EdgePolyline& line, double deviation);

} // namespace seamless
