// SPDX-License-Identifier: MIT
// Test helper: a welded mesh from literal positions and triangles.
#pragma once

#include <seamless/mesh/check/weld.h>

#include <array>
#include <utility>
#include <vector>

namespace seamless::test {

inline WeldedMesh welded(std::vector<Vec3> p, std::vector<std::array<int, 3>> t) {
    TriangleMesh m;
    m.positions = std::move(p);
    m.triangles = std::move(t);
    return weld_vertices(m);
}

} // namespace seamless::test
