// SPDX-License-Identifier: MIT
#include <seamless/mesh/check/edge_topology.h>
#include <seamless/mesh/check/self_intersections.h>

#include <catch2/catch.hpp>

#include "welded.h"

using namespace seamless;

using seamless::test::welded;

TEST_CASE("self_intersections: duplicates are hashed, each repeat paired with the first",
          "[check][self_intersections]") {
    const WeldedMesh w = welded({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}},
                                {{0, 1, 2}, {1, 3, 2}, {2, 1, 0}, {0, 1, 2}, {1, 2, 3}});
    const auto d = duplicated_triangles(w);
    REQUIRE(d.size() == 3);
    CHECK(d[0].t0 == 0);
    CHECK(d[0].t1 == 2); // the reverse orientation is the same vertex set
    CHECK(d[1].t0 == 0);
    CHECK(d[1].t1 == 3);
    CHECK(d[2].t0 == 1);
    CHECK(d[2].t1 == 4);
    // Copies take no part in the intersection pass: they are reported as duplicates.
    const std::vector<int> one_shell(5, 0);
    const Intersections i = find_intersections(w, one_shell, {}, d, {});
    CHECK(i.self_intersections.empty());
    CHECK(i.overlaps.empty());
}

TEST_CASE("self_intersections: degenerate triangles, exactly", "[check][self_intersections]") {
    // Three collinear points, a repeated vertex, and a point just off the line.
    const WeldedMesh w = welded({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {1.0 / 3, 1.0 / 3, 0.34}},
                                {{0, 1, 2}, {0, 0, 1}, {0, 1, 3}});
    const auto d = degenerate_triangles(w);
    REQUIRE(d.size() == 2);
    CHECK(d[0].triangle == 0);
    CHECK(d[1].triangle == 1);
}

TEST_CASE("self_intersections: crossing triangles within a shell and between shells",
          "[check][self_intersections]") {
    const WeldedMesh w =
        welded({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {1.5, 1.5, 0}},
               {{0, 1, 2}, {3, 4, 5}});
    const Intersections same = find_intersections(w, {0, 0}, {}, {}, {});
    REQUIRE(same.self_intersections.size() == 1);
    CHECK(same.self_intersections[0].t0 == 0);
    CHECK(same.overlaps.empty());
    const Intersections apart = find_intersections(w, {0, 1}, {}, {}, {});
    CHECK(apart.self_intersections.empty());
    CHECK(apart.overlaps.size() == 1);
}
