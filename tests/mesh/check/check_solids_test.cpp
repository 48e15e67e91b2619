// SPDX-License-Identifier: MIT
// Solids judged apart: two closed solids that touch are each closed and
// sound, their contact reported, not counted as a defect; a defect inside one
// solid still is one; --union judges the mesh whole as before.
#include "check_shapes.h"

#include "../../test_util.h"

#include <seamless/mesh/check/check.h>
#include <seamless/mesh/check/check_json.h>
#include <seamless/mesh/io/mesh_io.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

using namespace seamless;
using namespace seamless::test;

namespace {

// The box [lo, hi] as 12 outward triangles, each face split along the
// diagonal from its lowest corner, so two boxes sharing a face split it alike.
void add_box(TriangleMesh& m, Vec3 lo, Vec3 hi) {
    const int base = m.vertex_count();
    for (int k = 0; k < 8; ++k)
        m.positions.push_back({k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z});
    // Corners of each face counter-clockwise seen from outside, lowest first.
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces) {
        m.triangles.push_back({base + f[0], base + f[1], base + f[2]});
        m.triangles.push_back({base + f[0], base + f[2], base + f[3]});
    }
}

// The triangles added since ids was last filled get `solid`.
void mark(std::vector<int>& ids, const TriangleMesh& m, int solid) {
    ids.resize(m.triangles.size(), solid);
}

// Two unit boxes sharing the face x = 1 (bit-identical corners), solids 0 and 1.
TriangleMesh touching_boxes() {
    TriangleMesh m;
    add_box(m, {0, 0, 0}, {1, 1, 1});
    mark(m.triangle_solid, m, 0);
    add_box(m, {1, 0, 0}, {2, 1, 1});
    mark(m.triangle_solid, m, 1);
    return m;
}

CheckOptions closed(bool by_solid = true) {
    CheckOptions o;
    o.require_closed = true;
    o.by_solid = by_solid;
    return o;
}

} // namespace

TEST_CASE("check solids: two boxes sharing a face pass solid by solid, their contact reported",
          "[check][solids]") {
    const TriangleMesh m = touching_boxes();
    const CheckReport r = check_mesh(m, closed());
    CHECK(r.bodies == CheckBodies::solids);
    CHECK(r.body_count == 2);
    CHECK(defects(r) == Names{});
    CHECK(check_passed(r, closed()));
    CHECK(r.components.size() == 2);
    for (const auto& c : r.components) {
        CHECK(c.closed);
        CHECK(c.euler == 2);
        CHECK(c.outward == true);
    }
    CHECK(r.component_body == std::vector<int>{0, 1});
    CHECK(r.body_vertex_copies == 4); // the shared face's corners, judged in each box
    CHECK(r.vertices == 12);
    REQUIRE(r.body_contacts.size() == 1);
    CHECK(r.body_contacts[0].body0 == 0);
    CHECK(r.body_contacts[0].body1 == 1);
    CHECK(r.body_contacts[0].triangle_pairs == static_cast<int>(r.contacts.size()));
    CHECK(r.body_contacts[0].location.x > 0);
    CHECK(r.body_contacts[0].location.x < 2);
    for (const TrianglePair& p : r.contacts)
        CHECK(m.triangle_solid[p.t0] != m.triangle_solid[p.t1]);

    // Whole, the shared face is doubled and its edges non-manifold.
    const CheckReport u = check_mesh(m, closed(false));
    CHECK(u.bodies == CheckBodies::whole);
    CHECK(u.contacts.empty());
    CHECK_FALSE(check_passed(u, closed(false)));
    const Names d = defects(u);
    CHECK(std::count(d.begin(), d.end(), "non_manifold_edges") == 1);
    CHECK(std::count(d.begin(), d.end(), "duplicated_triangles") == 1);
}

TEST_CASE("check solids: interpenetrating boxes pass apart; parts stand in for missing solids",
          "[check][solids]") {
    TriangleMesh m;
    add_box(m, {0, 0, 0}, {1, 1, 1});
    mark(m.triangle_part, m, 3);
    add_box(m, {0.9, 0.2, 0.1}, {2, 0.8, 0.7}); // 0.1 into the first
    mark(m.triangle_part, m, 5);
    const CheckReport r = check_mesh(m, closed());
    CHECK(r.bodies == CheckBodies::parts);
    CHECK(check_passed(r, closed()));
    CHECK(r.overlaps.empty());
    REQUIRE(r.body_contacts.size() == 1);
    CHECK(r.body_contacts[0].body0 == 3);
    CHECK(r.body_contacts[0].body1 == 5);
    // Judged whole the two closed shells overlap: no defect either, as before.
    const CheckReport u = check_mesh(m, closed(false));
    CHECK(check_passed(u, closed(false)));
    CHECK(u.overlaps.size() == r.contacts.size());
}

TEST_CASE("check solids: a self-intersection inside one solid still fails", "[check][solids]") {
    TriangleMesh m = touching_boxes();
    // Box 0's corner (1, 1, 1) pushed through its bottom face.
    const int moved = 7;
    m.positions.push_back({0.5, 0.5, -0.5});
    for (size_t t = 0; t < 12; ++t)
        for (int& v : m.triangles[t])
            if (v == moved) v = m.vertex_count() - 1;
    const CheckReport r = check_mesh(m, closed());
    CHECK(r.bodies == CheckBodies::solids);
    CHECK_FALSE(check_passed(r, closed()));
    CHECK(defects(r) == Names{"self_intersections"});
    for (const TrianglePair& p : r.self_intersections) {
        CHECK(m.triangle_solid[p.t0] == 0);
        CHECK(m.triangle_solid[p.t1] == 0);
    }
}

TEST_CASE("check solids: solid ids through PLY, the CLI's text and JSON, and --union",
          "[check][solids]") {
    const auto dir = scratch_dir("check_solids");
    TriangleMesh m = touching_boxes();
    m.triangle_part.assign(m.triangles.size(), 0);
    m.triangle_face.resize(m.triangles.size());
    for (size_t t = 0; t < m.triangles.size(); ++t) m.triangle_face[t] = static_cast<int>(t / 2);
    m.part_names = {"boxes"};
    const auto ply = dir / "boxes.ply";
    write_mesh(ply, m);
    const TriangleMesh back = read_mesh(ply.string());
    CHECK(back.triangle_solid == m.triangle_solid);
    CHECK(back.triangle_face == m.triangle_face);

    auto r = run_cli("check --closed \"" + ply.string() + "\"");
    CHECK(r.status == 0);
    CHECK(r.out.find("judged apart: 2 solids") != std::string::npos);
    CHECK(r.out.find("solids 0 and 1: ") != std::string::npos);
    CHECK(r.out.find("shell 1 (solid 1)") != std::string::npos);
    r = run_cli("check --closed --json \"" + ply.string() + "\"");
    CHECK(r.status == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["bodies"] == "solids");
    CHECK(j["body_count"] == 2);
    CHECK(j["defects"] == 0);
    CHECK(j["contacts"]["count"].get<int>() > 0);
    CHECK(j["body_contacts"]["listed"][0]["bodies"] == nlohmann::json::array({0, 1}));
    CHECK(j["component_list"][1]["body"] == 1);
    r = run_cli("check --closed --union --json \"" + ply.string() + "\"");
    CHECK(r.status == 1);
    const auto u = nlohmann::json::parse(r.out);
    CHECK(u["bodies"] == "whole");
    CHECK(u["non_manifold_edges"]["count"].get<int>() > 0);
}
