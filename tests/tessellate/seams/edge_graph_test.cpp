// SPDX-License-Identifier: MIT
// The edge graph (issue 9, section 1): boundaries that meet by geometry, not
// by control polygon, tessellate crack-free: closed models stay closed, one
// shell, with the right Euler characteristic and no T-junction, at the
// section 8 tolerances and 100x finer.
#include <tessellate/mesh_properties.h>
#include <tessellate/seam_cases.h>

#include <seamless/model/model.h>
#include <seamless/tessellate/seams/edge_graph.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

using namespace seamless;

namespace {

Tessellation tessellate_at(const Model& m, double factor, double seam_tolerance) {
    TessellationOptions opt;
    opt.eps1 = 0.001 * d_max(m) / factor;
    opt.eps2 = 0.02 * d_max(m) / factor;
    opt.seam_tolerance = seam_tolerance;
    opt.certify = false; // topology only: the bound is error_bound_test's
    return tessellate(m, opt);
}

void check_closed(const test::SeamCase& c, double factor) {
    const Tessellation t = tessellate_at(c.model, factor, c.seam_tolerance);
    INFO(c.name << " at 1/" << factor << " of the default tolerances: " << t.stats.triangles
                << " triangles, " << t.stats.seams << " seams, " << t.stats.seam_vertices
                << " seam vertices");
    const test::MeshReport r = test::analyse_mesh(t.mesh, t.stats.d_max);
    INFO(r.example);
    CHECK(r.border_edges == 0);
    CHECK(r.nonmanifold_edges == 0);
    CHECK(r.misoriented_edges == 0);
    CHECK(r.t_junctions == 0);
    CHECK(r.duplicate_positions == 0);
    CHECK(r.zero_area == 0);
    CHECK(r.V == t.mesh.vertex_count());
    CHECK(r.euler() == 2);
    CHECK(test::count_shells(t.mesh) == 1);
    CHECK(t.stats.nonplanar_subpatches == 0);
    if (c.geometric) {
        CHECK(t.stats.seams > 0);
        CHECK(t.stats.seam_vertices > 0);
    } else {
        CHECK(t.stats.seams == 0);
    }
}

const test::SeamCase& closed_case(size_t i) {
    static const std::vector<test::SeamCase> all = test::closed_seam_cases();
    REQUIRE(i < all.size());
    return all[i];
}

} // namespace

TEST_CASE("closed seam cases tessellate closed at the default tolerances", "[edge_graph][heavy]") {
    for (const test::SeamCase& c : test::closed_seam_cases()) check_closed(c, 1);
}

// 100x finer: one test case each, so that ctest runs them in parallel.
#define SEAM_CASE_100X(i)                                                                          \
    TEST_CASE("closed seam case " #i " tessellates closed at 100x finer tolerances",               \
              "[edge_graph][fine][heavy]") {                                                       \
        check_closed(closed_case(i), 100);                                                         \
    }
SEAM_CASE_100X(0)
SEAM_CASE_100X(1)
SEAM_CASE_100X(2)
SEAM_CASE_100X(3)
SEAM_CASE_100X(4)
SEAM_CASE_100X(5)
SEAM_CASE_100X(6)
SEAM_CASE_100X(7)
SEAM_CASE_100X(8)

TEST_CASE("the seam case operations keep the surface", "[edge_graph]") {
    const BSplineSurface f = test::bulged_box_faces()[2];
    auto P = [](const BSplineSurface& s, double u, double v) { return evaluate(s, u, v).point; };
    const double t = std::sqrt(0.5);
    const std::vector<BSplineSurface> halves = test::split(f, 0, t);
    double worst = 0;
    for (double u : {0.0, 0.13, 0.5, 0.77, 1.0})
        for (double v : {0.0, 0.29, 0.61, 1.0}) {
            const Vec3 p = P(f, u, v);
            for (int dir = 0; dir < 2; ++dir) {
                const double a = dir == 0 ? u : v, b = dir == 0 ? v : u;
                auto at = [&](const BSplineSurface& s, double x) {
                    return dir == 0 ? P(s, x, b) : P(s, b, x);
                };
                worst = std::max(worst, distance(at(test::insert_knot(f, dir, t), a), p));
                worst = std::max(worst, distance(at(test::elevate(f, dir), a), p));
                worst = std::max(worst, distance(at(test::reverse(f, dir), 1 - a), p));
                // u -> c u + (1 - c) u^2 at x gives the old surface at phi(x).
                for (double c : {0.0, 0.5}) {
                    const double x = c == 0 ? std::sqrt(a) : (-0.5 + std::sqrt(0.25 + 2 * a));
                    worst = std::max(worst, distance(at(test::reparametrise(f, dir, c), x), p));
                }
                // Weights rho^i: x = a / (rho (1 - a) + a).
                const double rho = 2;
                const BSplineSurface r = test::rationalise(f, dir, rho);
                CHECK(r.rational());
                worst = std::max(worst, distance(at(r, a / (rho * (1 - a) + a)), p));
            }
            const Vec3 q = u <= t ? P(halves[0], u / t, v) : P(halves[1], (u - t) / (1 - t), v);
            worst = std::max(worst, distance(q, p));
        }
    CHECK(worst < 1e-14);
}

TEST_CASE("the same box with a gap of 1e-6 is not stitched at the default seam tolerance",
          "[edge_graph]") {
    for (const test::SeamCase& c : test::closed_seam_cases()) {
        if (c.seam_tolerance < 0) continue;
        INFO(c.name);
        const Tessellation t = tessellate_at(c.model, 1, -1);
        const test::MeshReport r = test::analyse_mesh(t.mesh, t.stats.d_max, false);
        CHECK(r.border_edges > 0);
        CHECK(r.nonmanifold_edges == 0);
        CHECK(t.stats.seam_tolerance < 1e-6);
    }
}

TEST_CASE("two sheets sharing x = 1, one with an extra knot along it, are one shell",
          "[edge_graph][heavy]") {
    for (double knot : {0.3, 0.5, std::sqrt(0.5)})
        for (double factor : {1.0, 100.0}) {
            const Model m = test::two_sheets(knot);
            const Tessellation t = tessellate_at(m, factor, -1);
            INFO("knot " << knot << ", 1/" << factor << " of the default tolerances");
            const test::MeshReport r = test::analyse_mesh(t.mesh, t.stats.d_max);
            INFO(r.example);
            CHECK(test::count_shells(t.mesh) == 1);
            CHECK(test::border_edges_where(
                      t.mesh, [](Vec3 p) { return std::abs(p.x - 1) < 1e-9 && p.y > 1e-9; }) == 0);
            CHECK(r.t_junctions == 0);
            CHECK(r.duplicate_positions == 0);
            CHECK(r.nonmanifold_edges == 0);
            CHECK(r.misoriented_edges == 0);
            CHECK(r.euler() == 1); // a disc
        }
}

TEST_CASE("two sheets 1e-6 apart are stitched within the seam tolerance, not beyond",
          "[edge_graph]") {
    const Model m = test::two_sheets(0.3, 1e-6);
    const auto on_seam = [](Vec3 p) { return std::abs(p.x - 1) < 1e-9 && p.y > 1e-9; };
    const Tessellation stitched = tessellate_at(m, 1, 1e-5);
    CHECK(test::count_shells(stitched.mesh) == 1);
    CHECK(test::border_edges_where(stitched.mesh, on_seam) == 0);
    const test::MeshReport r = test::analyse_mesh(stitched.mesh, stitched.stats.d_max);
    CHECK(r.t_junctions == 0);
    CHECK(r.euler() == 1);

    const Tessellation apart = tessellate_at(m, 1, -1);
    CHECK(test::count_shells(apart.mesh) == 2);
    CHECK(test::border_edges_where(apart.mesh, on_seam) > 0);
    CHECK(apart.stats.seams == 0);
}

TEST_CASE("boundaries that only cross or touch are no seam", "[edge_graph]") {
    // Sheet A in z = 0 over [0,1]^2, sheet B in x = 0.5 over y in [-1,0],
    // z in [-0.5,0.5]: their boundaries cross at (0.5, 0, 0), a patch corner
    // of B (a knot at 0.5) inside A's edge. Sheet C continues A beyond x = 1
    // and touches it at one corner only.
    auto plane = [](const char* name, Vec3 o, Vec3 a, Vec3 b) {
        std::vector<Vec3> pts;
        for (int i = 0; i <= 1; ++i)
            for (int j = 0; j <= 1; ++j) pts.push_back(o + double(i) * a + double(j) * b);
        return test::bezier_surface(name, 1, 1, pts);
    };
    const BSplineSurface A = plane("A", {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    const BSplineSurface B =
        test::insert_knot(plane("B", {0.5, -1, -0.5}, {0, 0, 1}, {0, 1, 0}), 0, 0.5);
    const BSplineSurface C = plane("C", {1, 1, 0}, {1, 0, 0}, {0, 1, 0});
    const Model m = test::model_of({A, B, C}, "crossing");
    const Tessellation t = tessellate(m, {});
    CHECK(t.stats.seams == 0);
    CHECK(t.stats.seam_vertices == 0);
    CHECK(test::count_shells(t.mesh) == 2); // A and C share a corner vertex, B apart
}

TEST_CASE("a chain of edges on one edge: both sides get the same vertices", "[edge_graph][heavy]") {
    // A T: the lower sheet's top edge against the edges of two upper sheets
    // (one upper sheet split at an irrational parameter), the left one refined
    // by two knots, the right one by one.
    auto sheet = [](const char* name, double y0) {
        std::vector<Vec3> pts;
        for (int i = 0; i <= 3; ++i)
            for (int j = 0; j <= 3; ++j) {
                const double x = 2 * i / 3.0, y = y0 + j / 3.0;
                pts.push_back({x, y, 0.3 * std::sin(2 * x) * std::cos(2 * y - 2)});
            }
        return test::bezier_surface(name, 3, 3, pts);
    };
    std::vector<BSplineSurface> top = test::split(sheet("top", 1), 0, std::sqrt(0.5) - 0.3);
    top[0] = test::insert_knot(test::insert_knot(top[0], 0, 0.3), 0, 0.6);
    top[1] = test::insert_knot(top[1], 0, 1 / std::sqrt(3.0));
    const Model m = test::model_of({sheet("lower", 0), top[0], top[1]}, "T");
    for (double factor : {1.0, 100.0}) {
        const Tessellation t = tessellate_at(m, factor, -1);
        const test::MeshReport r = test::analyse_mesh(t.mesh, t.stats.d_max);
        INFO("1/" << factor << ": " << r.example);
        CHECK(t.stats.seams >= 3);
        CHECK(test::count_shells(t.mesh) == 1);
        CHECK(test::border_edges_where(t.mesh, [](Vec3 p) {
                  return std::abs(p.y - 1) < 1e-9 && p.x > 1e-9 && p.x < 2 - 1e-9;
              }) == 0);
        CHECK(r.t_junctions == 0);
        CHECK(r.duplicate_positions == 0);
        CHECK(r.nonmanifold_edges == 0);
        CHECK(r.misoriented_edges == 0);
        CHECK(r.euler() == 1);
    }
}

TEST_CASE("a patch corner of one side is inserted into the other at its own parameter",
          "[edge_graph][heavy]") {
    // two_sheets: both sides of x = 1 run in v with the same parametrisation,
    // so the right sheet's patch corner at the knot lands on the left sheet's
    // edge at that parameter, and the left sheet's grid vertices are either
    // the right's (the same point) or inserted into the right's edges.
    const double knot = 0.3;
    const Model m = test::two_sheets(knot);
    const auto patches = bezier_patches(m);
    const Tessellation t = tessellate(m, patches, {});
    const BoundaryMatch bm = match_boundaries(patches, t.stats.seam_tolerance);
    const EdgeRegistry reg = build_edge_registry(bm, t.subpatches);
    const EdgeGraph g = build_edge_graph(patches, bm, reg, t.stats.seam_tolerance);
    CHECK(g.seams == t.stats.seams);
    CHECK(g.seam_vertices == t.stats.seam_vertices);
    // The left sheet (patch 0) edge u1 (x = 1) is one line.
    const int left = bm.edge_group[4 * 0 + 1];
    REQUIRE(left >= 0);
    const auto seam = seam_points(g, left);
    bool knot_found = false;
    for (const SeamPoint& p : seam) {
        CHECK(p.x > 0);
        CHECK(p.x < 1);
        knot_found = knot_found || std::abs(p.x - knot) < 1e-12;
    }
    CHECK(knot_found);
    // Sorted by parameter, and every one a vertex of some other line.
    for (size_t i = 1; i < seam.size(); ++i) CHECK(seam[i - 1].x < seam[i].x);
    for (const SeamPoint& p : seam) CHECK(p.key.kind != 2);
}

TEST_CASE("edges that overlap in part share the overlap only", "[edge_graph][heavy]") {
    // Lower sheet over x in [0, 1.5], upper over [0.5, 2], both cut from
    // sheets over [0, 2] that share the curve y = 1: the edges overlap on
    // [0.5, 1.5], where neither edge's end lies inside the other's range.
    auto sheet = [](const char* name, double y0) {
        std::vector<Vec3> pts;
        for (int i = 0; i <= 3; ++i)
            for (int j = 0; j <= 3; ++j) {
                const double x = 2 * i / 3.0, y = y0 + j / 3.0;
                pts.push_back({x, y, 0.4 * std::cos(2 * x) * std::sin(2 * y)});
            }
        return test::bezier_surface(name, 3, 3, pts);
    };
    const BSplineSurface lower = test::split(sheet("lower", 0), 0, 0.75)[0];
    const BSplineSurface upper =
        test::insert_knot(test::split(sheet("upper", 1), 0, 0.25)[1], 0, 1 / std::sqrt(5.0));
    const Model m = test::model_of({lower, upper}, "staggered");
    for (double factor : {1.0, 100.0}) {
        const Tessellation t = tessellate_at(m, factor, -1);
        const test::MeshReport r = test::analyse_mesh(t.mesh, t.stats.d_max);
        INFO("1/" << factor << ": " << r.example);
        CHECK(t.stats.seams > 0);
        CHECK(test::count_shells(t.mesh) == 1);
        CHECK(test::border_edges_where(t.mesh, [](Vec3 p) {
                  return std::abs(p.y - 1) < 1e-9 && p.x > 0.5 + 1e-9 && p.x < 1.5 - 1e-9;
              }) == 0);
        // Beyond the overlap the edges stay borders.
        CHECK(test::border_edges_where(t.mesh, [](Vec3 p) {
                  return std::abs(p.y - 1) < 1e-9 && (p.x < 0.5 - 1e-9 || p.x > 1.5 + 1e-9);
              }) > 0);
        CHECK(r.t_junctions == 0);
        CHECK(r.duplicate_positions == 0);
        CHECK(r.nonmanifold_edges == 0);
        CHECK(r.misoriented_edges == 0);
        CHECK(r.euler() == 1);
    }
}
