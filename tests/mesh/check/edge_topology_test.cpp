// SPDX-License-Identifier: MIT
#include <seamless/mesh/check/edge_topology.h>

#include <catch2/catch.hpp>

#include "welded.h"

using namespace seamless;

using seamless::test::welded;

TEST_CASE("edge_topology: borders, a non-manifold edge and a misoriented pair",
          "[check][edge_topology]") {
    // Three triangles on the edge 0-1 (non-manifold); 1-0-3 and 0-1-4 are
    // oriented alike on it, as are 0-1-2 and 0-1-4.
    const WeldedMesh w = welded({{0, 0, 0}, {0, 0, 1}, {1, 0, 0.5}, {-1, 0.2, 0.5}, {0, -1, 0.5}},
                                {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    const EdgeTopology e = edge_topology(w);
    CHECK(e.groups.size() == 7);
    CHECK(e.border.size() == 6);
    REQUIRE(e.non_manifold_edges.size() == 1);
    CHECK(e.non_manifold_edges[0].triangles == 3);
    CHECK(e.inconsistent_orientation.empty()); // judged only on edges of two triangles
    const Shells s = find_shells(w, e, {});
    CHECK(s.shells.size() == 1);
    CHECK(s.manifold_bad[0] == 1);
    CHECK(s.shells[0].border_edges == 6);
    CHECK_FALSE(s.shells[0].closed);

    // Two triangles traversing their shared edge in the same direction.
    const WeldedMesh f =
        welded({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {{0, 1, 2}, {1, 2, 3}});
    const EdgeTopology ef = edge_topology(f);
    REQUIRE(ef.inconsistent_orientation.size() == 1);
    CHECK(ef.inconsistent_orientation[0].location == Vec3{0.5, 0.5, 0});
}

TEST_CASE("edge_topology: border joins merge shells and fans", "[check][edge_topology]") {
    // Two triangles sharing only vertex 0: a bowtie, two shells and one contact;
    // a join at vertex 0 (their border edges lying along each other) makes them one.
    const WeldedMesh w =
        welded({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0.5}}, {{0, 1, 2}, {0, 3, 4}});
    const EdgeTopology e = edge_topology(w);
    const Shells apart = find_shells(w, e, {});
    CHECK(apart.shells.size() == 2);
    REQUIRE(apart.shell_contacts.size() == 1);
    CHECK(apart.shell_contacts[0].vertex == 0);
    CHECK(apart.triangle_shell == std::vector<int>{0, 1});
    const Shells joined = find_shells(w, e, {BorderJoin{0, 1, 0}});
    CHECK(joined.shells.size() == 1);
    CHECK(joined.shell_contacts.empty());
    CHECK(joined.non_manifold_vertices.empty());
    CHECK(joined.shells[0].vertices == 5);
}
