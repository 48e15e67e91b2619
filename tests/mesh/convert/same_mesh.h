// SPDX-License-Identifier: MIT
// What the conversion tests (openmesh_test.cpp, surface_mesh_test.cpp) share:
// the teapot's tessellation, with every attribute the tessellator fills, and a
// bit-for-bit comparison of two meshes.
#pragma once

#include "test_util.h"

#include <seamless/base/triangle_mesh.h>
#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

namespace seamless::test {

inline const TriangleMesh& teapot_mesh() {
    static const TriangleMesh mesh = tessellate(load_model(model_path("teapot.json")), {}).mesh;
    return mesh;
}

template <class T> bool same_elements(const std::vector<T>& a, const std::vector<T>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (!same_bytes(a[i], b[i])) return false;
    return true;
}

// Vertices, triangles (in order, corners in order) and the optional
// attributes, byte for byte (so -0 and +0 differ); names only when `names`.
inline void check_same_mesh(const TriangleMesh& a, const TriangleMesh& b, bool names) {
    CHECK(same_elements(a.positions, b.positions));
    CHECK(same_elements(a.triangles, b.triangles));
    CHECK(same_elements(a.triangle_surface, b.triangle_surface));
    CHECK(same_elements(a.corner_normals, b.corner_normals));
    CHECK(same_elements(a.corner_uvs, b.corner_uvs));
    if (names) CHECK(a.surface_names == b.surface_names);
}

// Two triangles on the edge (0,1) and a third on it too: an edge of three faces.
inline TriangleMesh three_faces_on_an_edge() {
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    m.triangles = {{0, 1, 2}, {1, 0, 3}, {1, 0, 4}};
    return m;
}

// Two triangles touching at vertex 0 only (a bowtie), with source surfaces.
inline TriangleMesh bowtie() {
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0.5}, {-1, -1, 0.5}};
    m.triangles = {{0, 1, 2}, {0, 3, 4}};
    m.triangle_surface = {0, 1};
    return m;
}

} // namespace seamless::test
