// SPDX-License-Identifier: MIT
// copy_pinched_vertices (lib/mesh/pinched_vertices.h): one copy per extra fan.
#include <seamless/mesh/pinched_vertices.h>

#include <catch2/catch.hpp>

using namespace seamless;

TEST_CASE("A vertex where fans meet gets a copy per extra fan", "[pinched]") {
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    SECTION("Three fans at vertex 0") {
        m.triangles = {{0, 1, 2}, {0, 3, 4}, {0, 5, 6}};
        const PinchedVertexCopies c = copy_pinched_vertices(m);
        CHECK(c.copy_of == std::vector<int>{0, 0});
        CHECK(c.triangles[0] == m.triangles[0]); // the first triangle's fan keeps the vertex
        CHECK(c.triangles[1] == std::array<int, 3>{7, 3, 4});
        CHECK(c.triangles[2] == std::array<int, 3>{8, 5, 6});
    }
    SECTION("One fan, joined across shared edges, is left alone") {
        m.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}, {5, 1, 2}};
        const PinchedVertexCopies c = copy_pinched_vertices(m);
        CHECK(c.copy_of.empty());
        CHECK(c.triangles == m.triangles);
    }
}
