// SPDX-License-Identifier: MIT
// The B-rep's mesh from its discretised edges and triangulated faces. Global
// vertex numbering: the B-rep's vertices first, then each edge's interior
// points in edge order, then each face's interior points in face order; a
// boundary vertex is its edge's 3D point, shared by every face using it.
#pragma once

#include <seamless/base/triangle_mesh.h>
#include <seamless/model/model.h>
#include <seamless/tessellate/trimmed/edge_discretisation.h>
#include <seamless/tessellate/trimmed/faces/face_triangulation.h>

#include <vector>

namespace seamless {

// `meshes[f].domain` empty (or failed) leaves face f out.
TriangleMesh brep_mesh(const Model& model, const std::vector<EdgePolyline>& lines,
                       const std::vector<FaceMesh>& meshes);

} // namespace seamless
