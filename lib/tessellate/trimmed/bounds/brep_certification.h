// SPDX-License-Identifier: MIT
// The certified deviation of a B-rep's mesh: the largest TriangleBound over
// its triangles (every point of a face the triangles cover is within it of
// the mesh, and back) and the largest ChordBound over its edges' segments
// (every point of an edge curve within it of its polyline, and back).
// Neither covers the sliver between a pcurve and its straight (u,v) chords,
// which the edge discretisation's sampled criterion keeps within the
// deviation; BRepStats says so.
#pragma once

#include <seamless/base/triangle_mesh.h>
#include <seamless/model/model.h>
#include <seamless/tessellate/trimmed/edge_discretisation.h>

#include <vector>

namespace seamless {

struct BRepBound {
    double triangles = 0, chords = 0; // model units; +infinity where not certifiable
};

// `mesh` is brep_mesh(model, lines, ...) (triangle_surface, corner_uvs set).
BRepBound certify_brep(const Model& model, const std::vector<EdgePolyline>& lines,
                       const TriangleMesh& mesh, int threads);

} // namespace seamless
