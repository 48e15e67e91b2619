// SPDX-License-Identifier: MIT
// Meshes built directly for the check's tests (check_test.cpp,
// check_files_test.cpp), and the defect kinds a report names.
#pragma once

#include <seamless/base/triangle_mesh.h>
#include <seamless/mesh/check/check.h>

#include <cmath>
#include <string>
#include <vector>

namespace seamless::test {

// A piece of the surface z = 0.3 sin(2x) over [x0, x1] x [0, 1] with its own
// vertices, nx by ny quads, shifted by `offset`. Two pieces meeting at the same x
// have bit-identical seam positions (same formula, same inputs).
inline void add_piece(TriangleMesh& m, double x0, double x1, int nx, int ny, Vec3 offset = {}) {
    const int base = m.vertex_count();
    for (int i = 0; i <= nx; ++i)
        for (int j = 0; j <= ny; ++j) {
            const double x = x0 + i * ((x1 - x0) / nx), y = static_cast<double>(j) / ny;
            m.positions.push_back(Vec3{x, y, 0.3 * std::sin(2 * x)} + offset);
        }
    auto id = [&](int i, int j) { return base + i * (ny + 1) + j; };
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j) {
            m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
}

inline TriangleMesh octahedron(Vec3 c = {}, double r = 1) {
    TriangleMesh m;
    for (Vec3 d : {Vec3{1, 0, 0}, Vec3{-1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, -1, 0}, Vec3{0, 0, 1},
                   Vec3{0, 0, -1}})
        m.positions.push_back(c + r * d);
    // Outward: counter-clockwise seen from outside.
    m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                   {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return m;
}

// The names of the defect kinds the report holds.
inline std::vector<std::string> defects(const CheckReport& r) {
    std::vector<std::string> d;
    if (!r.cracks.empty()) d.push_back("cracks");
    if (!r.t_junctions.empty()) d.push_back("t_junctions");
    if (!r.non_manifold_edges.empty()) d.push_back("non_manifold_edges");
    if (!r.non_manifold_vertices.empty()) d.push_back("non_manifold_vertices");
    if (!r.degenerate_triangles.empty()) d.push_back("degenerate_triangles");
    if (!r.duplicated_triangles.empty()) d.push_back("duplicated_triangles");
    if (!r.inconsistent_orientation.empty()) d.push_back("inconsistent_orientation");
    if (!r.self_intersections.empty()) d.push_back("self_intersections");
    return d;
}
using Names = std::vector<std::string>;

} // namespace seamless::test
