// SPDX-License-Identifier: MIT
// What a B-rep holds, counted: for `seamless info` and the --stats of the
// trimmed pipeline.
#pragma once

#include <seamless/model/brep.h>

namespace seamless {

struct BRepCounts {
    int solids = 0, shells = 0, closed_shells = 0, faces = 0, faces_with_holes = 0;
    int loops = 0, coedges = 0, edges = 0, seam_edges = 0, degenerate_edges = 0, vertices = 0;
    double max_edge_tolerance = 0, max_vertex_tolerance = 0; // model units
};

BRepCounts count(const BRep& b);

} // namespace seamless
