// SPDX-License-Identifier: MIT
#include <seamless/mesh/check/weld.h>

#include <catch2/catch.hpp>

using namespace seamless;

TEST_CASE("weld: bit-identical positions become the first such vertex", "[check][weld]") {
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},    {1, 0, 0},
                   {0, 1, 0}, {1, 1, 0}, {-0.0, 0, 0}, {5, 5, 5}};
    m.triangles = {{0, 1, 2}, {3, 5, 4}, {6, 1, 2}};
    const WeldedMesh w = weld_vertices(m);
    CHECK(w.welded_vertices == 2); // 3 -> 1, 4 -> 2; -0.0 differs from 0.0 in its bits
    CHECK(w.positions.size() == 6);
    CHECK(w.triangles[1] == std::array<int, 3>{1, 3, 2});
    CHECK(w.triangles[2][0] != w.triangles[0][0]);
    CHECK(w.unreferenced_vertices == 1); // (5, 5, 5)
    CHECK(std::count(w.referenced.begin(), w.referenced.end(), 1) == 5);

    const WeldedMesh raw = weld_vertices(m, false);
    CHECK(raw.welded_vertices == 0);
    CHECK(raw.positions == m.positions);
    CHECK(raw.triangles == m.triangles);
    CHECK(raw.unreferenced_vertices == 1);
}
