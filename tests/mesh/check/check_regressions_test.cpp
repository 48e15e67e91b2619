// SPDX-License-Identifier: MIT
// Regressions of check_mesh on hostile meshes (issue 12), each named after what
// broke. Sizes are those of the report; each finishes in well under a second
// in a Release build (no timing asserted).
#include <seamless/mesh/check/check.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace seamless;

TEST_CASE("check regression: 3001 tiny triangles and one long edge exploded the edge grid",
          "[check][regression]") {
    // Issue 12, finding 6: the grid was sized by the mean border edge (here
    // about 1e-3) and the long diagonal edge filled (1 / cell)^3 cells: 4 GB.
    TriangleMesh m;
    for (int k = 0; k < 3000; ++k) {
        const double x = 0.3 * k / 3000.0, y = 0.9, z = 0.1;
        const int b = m.vertex_count();
        m.positions.insert(m.positions.end(), {{x, y, z}, {x + 1e-5, y, z}, {x, y + 1e-5, z}});
        m.triangles.push_back({b, b + 1, b + 2});
    }
    const int b = m.vertex_count();
    m.positions.insert(m.positions.end(), {{0, 0, 0}, {1, 1, 1}, {1, 0.5, 0}});
    m.triangles.push_back({b, b + 1, b + 2});
    const CheckReport r = check_mesh(m);
    CHECK(r.triangles == 3001);
    CHECK(r.border_edges == 3 * 3001);
    CHECK(r.components.size() == 3001);
    CHECK(defect_count(r) == 0);
    CHECK(check_passed(r, {}));
}

TEST_CASE("check regression: 50000 copies of one triangle were quadratic", "[check][regression]") {
    // Issue 12, finding 7: the duplicate loop and the box-intersection callback
    // visited O(k^2) pairs. Copies are found by hashing and only the first takes
    // part in the intersection pass.
    TriangleMesh m;
    const int k = 50000;
    for (int i = 0; i < k; ++i) {
        const int b = m.vertex_count(); // each copy its own vertices, as in an STL file
        m.positions.insert(m.positions.end(), {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
        m.triangles.push_back({b, b + 1, b + 2});
    }
    const CheckReport r = check_mesh(m);
    CHECK_FALSE(check_passed(r, {}));
    CHECK(r.welded_vertices == 3 * k - 3);
    REQUIRE(r.duplicated_triangles.size() == k - 1);
    for (const TrianglePair& p : r.duplicated_triangles) CHECK(p.t0 == 0);
    CHECK(r.non_manifold_edges.size() == 3);
    CHECK(r.non_manifold_edges[0].triangles == k);
    CHECK(r.self_intersections.empty());
    CHECK(r.border_edges == 0);
}

TEST_CASE("check regression: 50000 unwelded copies of one triangle were quadratic",
          "[check][regression]") {
    // The same copies judged without welding (--no-weld): their indices differ,
    // so they are no duplicates but 50000 shells whose border edges lie on each
    // other. Edges with bit-identical end positions are compared once, triangles
    // with bit-identical corners intersect-tested once.
    TriangleMesh m;
    const int k = 50000;
    for (int i = 0; i < k; ++i) {
        const int b = m.vertex_count();
        m.positions.insert(m.positions.end(), {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
        m.triangles.push_back({b, b + 1, b + 2});
    }
    CheckOptions raw;
    raw.weld = false;
    const CheckReport r = check_mesh(m, raw);
    CHECK_FALSE(check_passed(r, raw));
    CHECK(r.components.size() == k);
    CHECK(r.border_edges == 3 * k);
    CHECK(r.cracks.size() == 3 * k); // every border edge lies on its copies
    CHECK(r.widest_crack == 0);
    REQUIRE(r.seams.size() == 1);
    CHECK(r.seams[0].length == Approx(k * (2 + std::sqrt(2.0)) / 2));
    CHECK(r.duplicated_triangles.empty());
    CHECK(r.t_junctions.empty());
}
