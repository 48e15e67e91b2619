// SPDX-License-Identifier: MIT
// With a tolerance, a subpatch whose ring is its four corners is two
// triangles where their certified bound and the angle allow it
// (Subpatch::diagonal, fan_certification.h): a plane is two triangles; a
// closed torus stays closed, conforming and without unused vertices, the
// same on 1 and 2 threads; surfaces that coincide near a tip (the fuselage's
// fin of no thickness) give no triangle twice.
#include <tessellate/mesh_properties.h>
#include <test_util.h>

#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <vector>

using namespace seamless;

namespace {

int quads(const Tessellation& t) {
    return static_cast<int>(std::count_if(t.subpatches.begin(), t.subpatches.end(),
                                          [](const Subpatch& sp) { return sp.diagonal >= 0; }));
}

// Triangles on the same three vertices, in any order.
int repeated_triangles(const TriangleMesh& m) {
    std::vector<std::array<int, 3>> sorted(m.triangles.begin(), m.triangles.end());
    for (auto& t : sorted) std::sort(t.begin(), t.end());
    std::sort(sorted.begin(), sorted.end());
    return static_cast<int>(sorted.end() - std::unique(sorted.begin(), sorted.end()));
}

} // namespace

TEST_CASE("two-triangle subpatches: a plane is two triangles", "[fan_triangles]") {
    BSplineSurface s;
    s.name = "plane";
    s.degree_u = s.degree_v = 1;
    s.size_u = s.size_v = 2;
    s.knots_u = s.knots_v = {0, 0, 1, 1};
    s.points = {{0, 0, 0}, {0, 1, 0.5}, {2, 0, 0}, {2, 1, 0.5}};
    Model m;
    m.surfaces.push_back(s);
    for (double angle : {0.0, 0.5}) {
        TessellationOptions o;
        o.tolerance = 1e-3;
        o.angle = angle;
        const Tessellation t = tessellate(m, o);
        CHECK(t.mesh.triangle_count() == 2);
        CHECK(t.mesh.vertex_count() == 4);
        CHECK(quads(t) == 1);
        CHECK(t.stats.max_error_bound < 1e-12);
    }
    // Without a tolerance the paper's fan of four stays.
    const Tessellation fan = tessellate(m, {});
    CHECK(fan.mesh.triangle_count() == 4);
    CHECK(quads(fan) == 0);
}

TEST_CASE("two-triangle subpatches: a torus stays closed and conforming",
          "[fan_triangles][heavy]") {
    const Model m = load_model(test::shared_dir() / "models/cad/torus.json");
    TessellationOptions o;
    o.tolerance = 1e-3 * d_max(m);
    o.angle = 0.5;
    o.threads = 1;
    const Tessellation t = tessellate(m, o);
    const int q = quads(t);
    CHECK(q > 0);
    CHECK(q < static_cast<int>(t.subpatches.size()));
    CHECK(t.stats.max_error_bound <= o.tolerance);
    const test::MeshReport r = test::analyse_mesh(t.mesh, d_max(m));
    CHECK(r.V == t.mesh.vertex_count()); // every vertex is a triangle's
    CHECK(r.border_edges == 0);
    CHECK(r.nonmanifold_edges == 0);
    CHECK(r.misoriented_edges == 0);
    CHECK(r.t_junctions == 0);
    CHECK(r.zero_area == 0);
    CHECK(r.euler() == 0);
    CHECK(repeated_triangles(t.mesh) == 0);
    o.threads = 2;
    const Tessellation t2 = tessellate(m, o);
    CHECK(t2.mesh.triangles == t.mesh.triangles);
    CHECK(t2.mesh.positions == t.mesh.positions);
}

TEST_CASE("two-triangle subpatches: surfaces coinciding near a tip give no triangle twice",
          "[fan_triangles][heavy]") {
    // The fuselage's two halves meet in a fin of no thickness at its tail:
    // there both sides' subpatches have the same three corners.
    const Model m = load_model(test::model_path("cad/bug28366_fuselage.json"));
    TessellationOptions o;
    o.tolerance = 1e-3 * 208.0;
    o.angle = 0.5;
    const Tessellation t = tessellate(m, o);
    CHECK(quads(t) > 0);
    CHECK(repeated_triangles(t.mesh) == 0);
    const test::MeshReport r = test::analyse_mesh(t.mesh, d_max(m));
    CHECK(r.nonmanifold_edges == 0);
    CHECK(r.border_edges == 0);
}
