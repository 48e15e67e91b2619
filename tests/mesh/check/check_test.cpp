// SPDX-License-Identifier: MIT
// The watertightness check on meshes built in memory: each defect kind, its
// tolerance, and CGAL's view of the same borders.
#include "check_shapes.h"

#include <seamless/mesh/check/check.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

using namespace seamless;
using namespace seamless::test;

namespace {

void append(TriangleMesh& m, const TriangleMesh& other) {
    const int base = m.vertex_count();
    m.positions.insert(m.positions.end(), other.positions.begin(), other.positions.end());
    for (auto t : other.triangles) m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

// A strip of width 1 in y swept along a polyline in the xz-plane, each segment
// cut into `cuts[k]` pieces; consistently oriented and manifold.
TriangleMesh sweep(const std::vector<std::array<double, 2>>& path, const std::vector<int>& cuts) {
    std::vector<std::array<double, 2>> pts{path[0]};
    for (size_t k = 0; k + 1 < path.size(); ++k)
        for (int s = 1; s <= cuts[k]; ++s) {
            const double t = static_cast<double>(s) / cuts[k];
            pts.push_back({path[k][0] + t * (path[k + 1][0] - path[k][0]),
                           path[k][1] + t * (path[k + 1][1] - path[k][1])});
        }
    TriangleMesh m;
    for (auto p : pts) {
        m.positions.push_back({p[0], 0, p[1]});
        m.positions.push_back({p[0], 1, p[1]});
    }
    for (int i = 0; i + 1 < static_cast<int>(pts.size()); ++i) {
        m.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 3});
        m.triangles.push_back({2 * i, 2 * i + 3, 2 * i + 1});
    }
    return m;
}

// CGAL's own view of a manifold mesh: vertices welded as check does (bit-identical
// positions) unless `weld` is false; returns {border halfedges, is_closed}.
std::pair<int, bool> cgal_borders(const TriangleMesh& m, bool weld) {
    using P = CGAL::Simple_cartesian<double>::Point_3;
    CGAL::Surface_mesh<P> sm;
    std::map<std::array<double, 3>, CGAL::Surface_mesh<P>::Vertex_index> by_pos;
    std::vector<CGAL::Surface_mesh<P>::Vertex_index> vid;
    for (Vec3 p : m.positions) {
        std::array<double, 3> k{p.x, p.y, p.z};
        if (!weld || !by_pos.count(k)) by_pos[k] = sm.add_vertex(P(p.x, p.y, p.z));
        vid.push_back(weld ? by_pos[k]
                           : CGAL::Surface_mesh<P>::Vertex_index(sm.num_vertices() - 1));
    }
    for (auto t : m.triangles) {
        auto f = sm.add_face(vid[t[0]], vid[t[1]], vid[t[2]]);
        REQUIRE(f != CGAL::Surface_mesh<P>::null_face());
    }
    int border = 0;
    for (auto h : sm.halfedges()) border += sm.is_border(h);
    return {border, CGAL::is_closed(sm)};
}

void agrees_with_cgal(const TriangleMesh& m, const CheckReport& r, bool weld = true) {
    auto [border, closed] = cgal_borders(m, weld);
    CHECK(r.border_edges == border);
    CHECK(r.closed == closed);
}

} // namespace

TEST_CASE("check: a seam of coincident unshared vertices is welded, or a crack of gap 0") {
    TriangleMesh m;
    add_piece(m, 0, 0.5, 2, 4);
    add_piece(m, 0.5, 1, 2, 4);
    const CheckReport r = check_mesh(m);
    CHECK(r.welded_vertices == 5);
    CHECK(defects(r) == Names{});
    CHECK(r.components.size() == 1);
    CHECK(r.border_loops.size() == 1);
    CHECK(r.border_loops[0].edges == 16);
    // Two sides of length 1 plus the curve z = 0.3 sin(2x) twice (chords: a bit over 1).
    CHECK(r.border_loops[0].length > 4);
    CHECK(r.border_loops[0].length < 4.5);
    CHECK(r.border_loops[0].closed);
    agrees_with_cgal(m, r);

    CheckOptions raw;
    raw.weld = false;
    const CheckReport n = check_mesh(m, raw);
    CHECK(n.welded_vertices == 0);
    CHECK(defects(n) == Names{"cracks"});
    CHECK(n.cracks.size() == 8); // 4 seam edges on either side
    CHECK(n.widest_crack == 0);
    CHECK(n.components.size() == 2);
    agrees_with_cgal(m, n, false);
}

TEST_CASE("check: a T-junction") {
    TriangleMesh m;
    add_piece(m, 0, 0.5, 2, 2);
    add_piece(m, 0.5, 1, 2, 4);
    const CheckReport r = check_mesh(m);
    // The seam's 2 + 4 edges run along each other: crack edges of one seam, with
    // the T-junctions where the finer side's vertices lie inside the coarser edges.
    CHECK(defects(r) == Names{"cracks", "t_junctions"});
    CHECK(r.cracks.size() == 6);
    REQUIRE(r.seams.size() == 1);
    CHECK(r.seams[0].length == Approx(1));
    CHECK(r.seams[0].location.x == 0.5);
    CHECK(r.components.size() == 1); // the sides share the seam's ends and middle
    REQUIRE(r.t_junctions.size() == 2);
    CHECK(r.t_junctions[0].position.x == 0.5);
    CHECK((r.t_junctions[0].position.y == 0.25 || r.t_junctions[0].position.y == 0.75));
    CHECK(r.t_junctions[0].distance < 1e-12);
    agrees_with_cgal(m, r);
}

TEST_CASE("check: gaps below the tolerance are cracks, above it plain borders") {
    const double d_max = 1.0; // the pieces span x in [0, 1 + tiny]
    SECTION("gap 1e-7 * d_max: a crack by default") {
        TriangleMesh m;
        add_piece(m, 0, 0.5, 2, 4);
        add_piece(m, 0.5, 1, 2, 4, {1e-7 * d_max, 0, 0});
        const CheckReport r = check_mesh(m);
        CHECK(r.welded_vertices == 0);
        CHECK(defects(r) == Names{"cracks"});
        CHECK(r.cracks.size() == 8);
        CHECK(r.widest_crack == Approx(1e-7).epsilon(1e-6));
        agrees_with_cgal(m, r);
    }
    SECTION("gap 1e-4 (0.04% of the seam edges): a crack by default, a border with --gap 1e-5") {
        TriangleMesh m;
        add_piece(m, 0, 0.5, 2, 4);
        add_piece(m, 0.5, 1, 2, 4, {1e-4 * d_max, 0, 0});
        const CheckReport r = check_mesh(m);
        CHECK(defects(r) == Names{"cracks"});
        CHECK(r.cracks.size() == 8);
        CHECK(r.seams.size() == 1);
        CHECK(r.widest_crack == Approx(1e-4).epsilon(1e-6));
        agrees_with_cgal(m, r);
        CheckOptions tight;
        tight.gap = 1e-5 * r.d_max;
        const CheckReport t = check_mesh(m, tight);
        CHECK(defects(t) == Names{});
        CHECK(t.border_loops.size() == 2);
        CHECK(t.border_edges == 24);
    }
    SECTION("gap 0.01 (4% of the seam edges): a border by default, a crack with --gap 0.02") {
        TriangleMesh m;
        add_piece(m, 0, 0.5, 2, 4);
        add_piece(m, 0.5, 1, 2, 4, {0.01, 0, 0});
        const CheckReport r = check_mesh(m);
        CHECK(defects(r) == Names{});
        CHECK(r.border_loops.size() == 2);
        agrees_with_cgal(m, r);
        CheckOptions wide;
        wide.gap = 0.02;
        const CheckReport w = check_mesh(m, wide);
        CHECK(defects(w) == Names{"cracks"});
        CHECK(w.widest_crack == Approx(0.01).epsilon(1e-6));
    }
}

TEST_CASE("check: a closed octahedron") {
    const TriangleMesh m = octahedron();
    const CheckReport r = check_mesh(m);
    CHECK(defects(r) == Names{});
    CHECK(r.closed);
    CHECK(r.edges == 12);
    REQUIRE(r.components.size() == 1);
    const auto& c = r.components[0];
    CHECK(c.euler == 2);
    CHECK(c.genus == 0);
    REQUIRE(c.volume);
    CHECK(*c.volume == Approx(4.0 / 3.0));
    CHECK(c.outward == true);
    agrees_with_cgal(m, r);
    CheckOptions closed;
    closed.require_closed = true;
    CHECK(check_passed(r, closed));

    // Turned inside out: still no defect, but not outward and negative volume.
    TriangleMesh inv = m;
    for (auto& t : inv.triangles) std::swap(t[1], t[2]);
    const CheckReport ri = check_mesh(inv);
    CHECK(defects(ri) == Names{});
    CHECK(ri.components[0].outward == false);
    CHECK(*ri.components[0].volume == Approx(-4.0 / 3.0));
}

TEST_CASE("check: a torus has genus 1") {
    TriangleMesh m;
    const int nu = 12, nv = 8;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
            m.positions.push_back({(2 + 0.5 * std::cos(v)) * std::cos(u),
                                   (2 + 0.5 * std::cos(v)) * std::sin(u), 0.5 * std::sin(v)});
        }
    auto id = [&](int i, int j) { return (i % nu) * nv + (j % nv); };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    const CheckReport r = check_mesh(m);
    CHECK(defects(r) == Names{});
    REQUIRE(r.components.size() == 1);
    CHECK(r.components[0].euler == 0);
    CHECK(r.components[0].genus == 1);
    CHECK(r.components[0].outward == true);
    CHECK(*r.components[0].volume > 0);
    agrees_with_cgal(m, r);
}

TEST_CASE("check: a flipped triangle") {
    TriangleMesh m = octahedron();
    std::swap(m.triangles[3][1], m.triangles[3][2]);
    const CheckReport r = check_mesh(m);
    CHECK(defects(r) == Names{"inconsistent_orientation"});
    CHECK(r.inconsistent_orientation.size() == 3);
    CHECK(r.closed);
    CHECK_FALSE(r.components[0].outward.has_value());
}

TEST_CASE("check: a non-manifold edge") {
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0.5}, {-1, 0.2, 0.5}, {0, -1, 0.5}};
    m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    const CheckReport r = check_mesh(m);
    CHECK(defects(r) == Names{"non_manifold_edges"});
    REQUIRE(r.non_manifold_edges.size() == 1);
    CHECK(r.non_manifold_edges[0].triangles == 3);
}

TEST_CASE("check: two shells touching at a vertex (a bowtie) are a shell contact") {
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0.5}};
    m.triangles = {{0, 1, 2}, {0, 3, 4}};
    const CheckReport r = check_mesh(m);
    CHECK(defects(r) == Names{});
    CHECK(r.components.size() == 2);
    REQUIRE(r.shell_contacts.size() == 1);
    CHECK(r.shell_contacts[0].vertex == 0);
    CHECK(r.shell_contacts[0].position == Vec3{0, 0, 0});
    CHECK(r.overlaps.empty());                                 // touching at the shared vertex only
    for (const auto& c : r.components) CHECK(c.vertices == 3); // the contact counts in each
}

TEST_CASE("check: a shell pinched at a vertex is non-manifold") {
    // A planar ring of quads around the hole [-1, 1]^2, one quad (x in [1, 2],
    // y in [-1, 1]) replaced by two triangles meeting at its centre O: the ring,
    // one shell through its edges, touches itself at O and nowhere else.
    TriangleMesh m;
    const double xs[4] = {-2, -1, 1, 2};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) m.positions.push_back({xs[i], xs[j], 0});
    auto id = [](int i, int j) { return 4 * i + j; };
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            if (j == 1 && i >= 1) continue; // the hole and the pinched quad
            m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    const int o = m.vertex_count();
    m.positions.push_back({1.5, 0, 0});
    m.triangles.push_back({id(2, 1), id(3, 1), o});
    m.triangles.push_back({id(3, 2), id(2, 2), o});
    const CheckReport r = check_mesh(m);
    CHECK(defects(r) == Names{"non_manifold_vertices"});
    REQUIRE(r.non_manifold_vertices.size() == 1);
    CHECK(r.non_manifold_vertices[0].position == Vec3{1.5, 0, 0});
    CHECK(r.shell_contacts.empty());
    CHECK(r.components.size() == 1);
    CHECK(r.overlaps.empty());
}

TEST_CASE("check: a zero-area triangle") {
    TriangleMesh m;
    add_piece(m, 0, 1, 2, 2);
    const int b = m.vertex_count();
    m.positions.insert(m.positions.end(), {{0, 3, 0}, {1, 3, 0}, {2, 3, 0}});
    m.triangles.push_back({b, b + 1, b + 2});
    const CheckReport r = check_mesh(m);
    CHECK(defects(r) == Names{"degenerate_triangles"});
    REQUIRE(r.degenerate_triangles.size() == 1);
    CHECK(r.degenerate_triangles[0].triangle == m.triangle_count() - 1);
}

TEST_CASE("check: a duplicated triangle") {
    TriangleMesh m;
    add_piece(m, 0, 1, 2, 2);
    m.triangles.push_back(m.triangles[3]);
    const CheckReport r = check_mesh(m);
    const Names d = defects(r);
    CHECK(std::count(d.begin(), d.end(), "duplicated_triangles") == 1);
    REQUIRE(r.duplicated_triangles.size() == 1);
    CHECK(r.duplicated_triangles[0].t0 == 3);
}

TEST_CASE("check: a self-intersection inside one component") {
    // Out along z = 0, up, back over, and down through the first part at x = 2.5.
    const TriangleMesh m = sweep({{0, 0}, {4, 0}, {4, 1}, {2.5, 1}, {2.5, -1}}, {4, 1, 1, 3});
    const CheckReport r = check_mesh(m);
    CHECK(defects(r) == Names{"self_intersections"});
    CHECK(r.self_intersections.size() >= 2);
    CHECK(r.overlaps.empty());
    CHECK(r.components.size() == 1);
    agrees_with_cgal(m, r);
    // The same strip without the last segment does not intersect itself.
    const TriangleMesh ok = sweep({{0, 0}, {4, 0}, {4, 1}, {2.5, 1}}, {4, 1, 1});
    CHECK(defects(check_mesh(ok)) == Names{});
}

TEST_CASE("check: two overlapping closed components are no defect") {
    TriangleMesh m = octahedron();
    append(m, octahedron({0.5, 0.3, 0.2}, 0.8));
    const CheckReport r = check_mesh(m);
    CHECK(defects(r) == Names{});
    CHECK(r.components.size() == 2);
    CHECK_FALSE(r.overlaps.empty());
    CHECK(r.self_intersections.empty());
    for (const auto& c : r.components) {
        CHECK(c.closed);
        CHECK(c.euler == 2);
    }
    agrees_with_cgal(m, r);
}
