// SPDX-License-Identifier: MIT
// Indexed triangle mesh: the output of tessellation and the input of export,
// check and the TRAY renderer. Plain arrays (libigl style), no library types.
#pragma once

#include <seamless/base/vec.h>

#include <array>
#include <string>
#include <vector>

namespace seamless {

struct TriangleMesh {
    // positions: #V, model units. Every geometric point is one vertex.
    std::vector<Vec3> positions;
    // triangles: #F vertex index triples, oriented consistently with the source
    // surface's (u,v) normal dP/du x dP/dv.
    std::vector<std::array<int, 3>> triangles;

    // Optional per-triangle and per-corner attributes (empty when absent):
    // triangle_surface: #F index of the source surface (into surface_names).
    std::vector<int> triangle_surface;
    // corner_normals: #F x 3 unit exact surface normals at the triangle's corners.
    std::vector<std::array<Vec3, 3>> corner_normals;
    // corner_uvs: #F x 3 (u,v) of each corner on the triangle's source surface
    // (per corner: a seam vertex has different (u,v) on either side).
    std::vector<std::array<std::array<double, 2>, 3>> corner_uvs;
    // surface_names: one per source surface.
    std::vector<std::string> surface_names;
    // Face ids (docs/formats.md, "Face ids"): triangle_face: #F index of the
    // B-rep face each triangle lies on (-1: none); triangle_part: #F index of
    // its part (into part_names; -1: none). Set by placed_mesh
    // (mesh/io/placed_mesh.h) and by the readers of files that carry them.
    std::vector<int> triangle_face, triangle_part;
    std::vector<std::string> part_names;
    // triangle_solid: #F index of the solid its face belongs to, one per
    // solid as placed (instance after instance; -1: a face in no solid), so
    // that `check` judges each solid apart (empty when absent).
    std::vector<int> triangle_solid;

    int vertex_count() const { return static_cast<int>(positions.size()); }
    int triangle_count() const { return static_cast<int>(triangles.size()); }
};

} // namespace seamless
