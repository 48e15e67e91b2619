// SPDX-License-Identifier: MIT
// Seam cracks (issue 9, section 2): border edges running along border edges or
// through border vertices, of the same shell or another, at the default gap
// rule (1% of the local edge length) and with an absolute gap.
#include "seam_sheets.h"

#include <seamless/mesh/check/check.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace seamless;
using test::divisions;
using test::merged;
using test::two_sheets;

namespace {

// Every crack lies on a seam, and the seams' edges add up to the cracks.
void seams_cover_cracks(const CheckReport& r) {
    int edges = 0;
    for (const Seam& s : r.seams) edges += s.edges;
    CHECK(edges == static_cast<int>(r.cracks.size()));
    for (const Crack& c : r.cracks) {
        CHECK(c.seam >= 0);
        CHECK(c.seam < static_cast<int>(r.seams.size()));
        CHECK(c.gap <= r.widest_crack);
    }
}

} // namespace

TEST_CASE("seam: two sheets 1e-4 apart with 10 and 7 edges along x = 0 are one crack seam",
          "[check][seam]") {
    const TriangleMesh m = two_sheets(divisions(10), divisions(7), 1e-4);
    const CheckReport r = check_mesh(m);
    CHECK_FALSE(check_passed(r, {}));
    CHECK(r.welded_vertices == 0);
    CHECK(r.components.size() == 2); // the sheets share no vertex
    // All 10 + 7 seam edges are crack edges of one seam along x = 0, y in [0, 1].
    CHECK(r.cracks.size() == 17);
    REQUIRE(r.seams.size() == 1);
    const Seam& s = r.seams[0];
    CHECK(s.edges == 17);
    CHECK(s.length == Approx(1).epsilon(1e-6));
    CHECK(s.gap == Approx(1e-4).epsilon(1e-6));
    CHECK(std::abs(s.location.x) <= 1e-4);
    CHECK(s.location.y > 0.3);
    CHECK(s.location.y < 0.7);
    CHECK(std::min(s.from.y, s.to.y) == 0);
    CHECK(std::max(s.from.y, s.to.y) == 1);
    CHECK(r.widest_crack == Approx(1e-4).epsilon(1e-6));
    // Each side's inner seam vertices lie inside the other side's edges.
    CHECK(r.t_junctions.size() == 9 + 6);
    for (const TJunction& t : r.t_junctions) CHECK(t.distance == Approx(1e-4).epsilon(1e-6));
    seams_cover_cracks(r);
    // No other defect: only borders along borders.
    CHECK(defect_count(r) == 17 + 15);
}

TEST_CASE("seam: the same sheets sharing their seam vertices pass", "[check][seam]") {
    // Both sides use the merged parameters on the seam: welded into one edge chain.
    const auto seam = merged(divisions(10), divisions(7));
    const TriangleMesh m = two_sheets(seam, seam, 0);
    const CheckReport r = check_mesh(m);
    CHECK(r.welded_vertices == static_cast<int>(seam.size()));
    CHECK(defect_count(r) == 0);
    CHECK(check_passed(r, {}));
    CHECK(r.components.size() == 1);
    CHECK(r.seams.empty());
    REQUIRE(r.border_loops.size() == 1);
    CHECK(r.border_loops[0].closed);
}

TEST_CASE("seam: a T-junction seam fails, at distance 0 and at 3e-18", "[check][seam]") {
    // Side B's seam has the vertices of both sides; side A only its own 10 edges,
    // so B's vertices at k/7 lie inside A's edges.
    const auto seam_b = merged(divisions(10), divisions(7));
    for (double gap : {0.0, 3e-18}) {
        INFO("gap " << gap);
        const TriangleMesh m = two_sheets(divisions(10), seam_b, gap);
        const CheckReport r = check_mesh(m);
        CHECK_FALSE(check_passed(r, {}));
        CHECK(r.t_junctions.size() == 6);
        for (const TJunction& t : r.t_junctions) CHECK(t.distance <= 3e-18);
        if (gap == 0) {
            // Where both sides have the same vertices the edge is shared (stitched);
            // the 6 edges of A holding a vertex k/7 of B, and B's 12 halves of them,
            // are crack edges, in 3 seams: y in [0.1, 0.3], [0.4, 0.6], [0.7, 0.9].
            CHECK(r.cracks.size() == 18);
            REQUIRE(r.seams.size() == 3);
            for (const Seam& s : r.seams) {
                CHECK(s.edges == 6);
                CHECK(s.length == Approx(0.2).epsilon(1e-12));
                CHECK(s.location.x == 0);
            }
            CHECK(r.components.size() == 1); // the sides share vertices: one shell
        } else {
            // Nothing is welded: all 10 + 16 seam edges are crack edges of one seam.
            CHECK(r.cracks.size() == 26);
            REQUIRE(r.seams.size() == 1);
            CHECK(r.seams[0].length == Approx(1).epsilon(1e-12));
            CHECK(std::abs(r.seams[0].location.x) <= 3e-18);
            CHECK(r.components.size() == 2);
        }
        seams_cover_cracks(r);
        CHECK(r.non_manifold_vertices.empty());
        CHECK(r.self_intersections.empty());
    }
}

TEST_CASE("seam: a true opening stays a border", "[check][seam]") {
    // Two border loops 0.1 apart on edges 1/7 (about 0.14) long, like the
    // teapot's lid above its rim.
    const TriangleMesh m = two_sheets(divisions(7), divisions(7), 0.1, 7, 7);
    const CheckReport r = check_mesh(m);
    CHECK(defect_count(r) == 0);
    CHECK(check_passed(r, {}));
    CHECK(r.border_loops.size() == 2);
    CHECK(r.seams.empty());
    // 2% of the edge length is beyond the default rule too.
    const TriangleMesh near = two_sheets(divisions(10), divisions(7), 0.002);
    CHECK(defect_count(check_mesh(near)) == 0);
}

TEST_CASE("seam: --gap sets an absolute tolerance", "[check][seam]") {
    const TriangleMesh m = two_sheets(divisions(10), divisions(7), 1e-4);
    CheckOptions tight;
    tight.gap = 1e-5;
    const CheckReport t = check_mesh(m, tight);
    CHECK(t.gap.absolute == 1e-5);
    CHECK(t.gap.relative == 0);
    CHECK(defect_count(t) == 0);
    CHECK(t.border_loops.size() == 2);
    CheckOptions wide;
    wide.gap = 0.05; // beyond 1% of the edges: the absolute tolerance decides
    const TriangleMesh apart = two_sheets(divisions(10), divisions(7), 0.01);
    CHECK(defect_count(check_mesh(apart)) == 0);
    const CheckReport w = check_mesh(apart, wide);
    CHECK(w.seams.size() == 1);
    CHECK(w.widest_crack == Approx(0.01).epsilon(1e-9));
}

TEST_CASE("seam: a border folding back along itself is a crack of one shell", "[check][seam]") {
    // One strip whose top border returns along itself: a triangle fan whose last
    // edge lies along its first, 1e-5 above it.
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {1, 1e-5, 1e-3}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    const CheckReport r = check_mesh(m);
    CHECK(r.components.size() == 1);
    CHECK_FALSE(r.cracks.empty());
    REQUIRE(r.seams.size() == 1);
    CHECK(r.seams[0].gap <= 1e-3 * 1.01);
    CHECK(r.non_manifold_vertices.empty());
}
