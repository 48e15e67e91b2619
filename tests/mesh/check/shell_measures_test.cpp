// SPDX-License-Identifier: MIT
#include <seamless/mesh/check/shell_measures.h>

#include <catch2/catch.hpp>

using namespace seamless;

TEST_CASE("shell_measures: a closed tetrahedron and an open one", "[check][shell_measures]") {
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}; // outward
    const WeldedMesh w = weld_vertices(m);
    Shells s = find_shells(w, edge_topology(w), {});
    measure_closed_shells(w, s);
    REQUIRE(s.shells.size() == 1);
    const ComponentReport& c = s.shells[0];
    CHECK(c.closed);
    CHECK(c.euler == 2);
    CHECK(c.genus == 0);
    REQUIRE(c.volume);
    CHECK(*c.volume == Approx(1.0 / 6));
    CHECK(c.outward == true);

    m.triangles.pop_back();
    const WeldedMesh o = weld_vertices(m);
    Shells open = find_shells(o, edge_topology(o), {});
    measure_closed_shells(o, open);
    CHECK_FALSE(open.shells[0].closed);
    CHECK_FALSE(open.shells[0].euler.has_value());
    CHECK_FALSE(open.shells[0].volume.has_value());
}
