// SPDX-License-Identifier: MIT
// Crack-free tessellation (paper section 6, Fig. 3) of the bundled and CAD models
// at the section 8 tolerances and 100x finer: no T-junctions, one vertex
// per point, interior edges shared by two oppositely oriented triangles, closed models closed with
// the right Euler characteristic; the naive rule cracks.
#include "mesh_properties.h"
#include "test_util.h"

#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

using namespace seamless;

namespace {

struct Case {
    std::filesystem::path path;
    int euler = 0;              // expected V - E + F when closed
    bool closed = false;        // no border edges expected
    bool free_overlaps = false; // free boundaries that overlap (teaspoon tips)
    // Stiff: weights 1e-3 .. 1e3 squeeze the surface near each corner into a
    // parameter region of about 1e-3, so at 100x finer tolerances the corner
    // subpatches reach max_depth before they are planar, and the fans there
    // fold slivers over (see check_crack_free). The mesh must still be
    // crack-free and consistently oriented edge by edge.
    bool stiff_weights = false;
};

std::vector<Case> cases() {
    std::vector<Case> out{{test::model_path("teapot.json")},
                          {test::model_path("teacup.json")},
                          {test::model_path("teaspoon.json"), 0, false, true},
                          {test::shared_dir() / "models/cad/torus.json", 0, true},
                          {test::shared_dir() / "models/cad/rounded_cube.json", 2, true}};
    out.push_back({test::model_path("torus.json"), 0, true});
    out.push_back({test::model_path("sphere.json"), 2, true});
    out.push_back({test::model_path("torus_exact.json"), 0, true});
    out.push_back({test::model_path("quarter_cylinder.json")});
    out.push_back({test::model_path("repeated_knot.json")});
    out.push_back({test::model_path("bilinear.json")});
    out.push_back({test::model_path("extreme_weights.json"), 0, false, false, true});
    return out;
}

// The case whose path ends with `key` ("models/teapot.json", "cad/torus.json").
const Case& model_case(const std::string& key) {
    static const std::vector<Case> all = cases();
    for (const Case& c : all) {
        const std::string p = c.path.generic_string();
        if (p.size() >= key.size() && p.compare(p.size() - key.size(), key.size(), key) == 0)
            return c;
    }
    const std::string& file = key;
    FAIL("no test case for " << file);
    return all.front();
}

void check_crack_free(const Case& c, double factor, bool t_junctions) {
    const Model m = load_model(c.path);
    TessellationOptions opt;
    opt.eps1 = 0.001 * d_max(m) / factor;
    opt.eps2 = 0.02 * d_max(m) / factor;
    opt.certify = false; // topology only: the bound is error_bound_test's
    const Tessellation t = tessellate(m, opt);
    INFO(c.path.filename().string() << " at 1/" << factor << " of the default tolerances: "
                                    << t.stats.triangles << " triangles");
    const TriangleMesh& mesh = t.mesh;
    REQUIRE(mesh.triangle_count() > 0);
    REQUIRE(mesh.triangle_surface.size() == mesh.triangles.size());
    REQUIRE(mesh.corner_normals.size() == mesh.triangles.size());
    REQUIRE(mesh.corner_uvs.size() == mesh.triangles.size());
    REQUIRE(mesh.surface_names.size() == m.surfaces.size());
    if (!c.stiff_weights) CHECK(t.stats.nonplanar_subpatches == 0);

    const test::MeshReport r =
        test::analyse_mesh(mesh, t.stats.d_max, t_junctions, c.free_overlaps);
    CHECK(r.duplicate_positions == 0);
    CHECK(r.zero_area == 0);
    INFO(r.example);
    CHECK(r.t_junctions == 0);
    CHECK(r.nonmanifold_edges == 0);
    CHECK(r.misoriented_edges == 0);
    CHECK(r.V == mesh.vertex_count()); // no unused vertex
    if (c.closed) {
        CHECK(r.border_edges == 0);
        CHECK(r.euler() == c.euler);
    }
    // Normals are unit and agree with the triangles' orientation.
    int agree = 0, not_unit = 0;
    double area = 0, folded_area = 0;
    for (int f = 0; f < mesh.triangle_count(); ++f) {
        const auto& tr = mesh.triangles[f];
        const Vec3 n = cross(mesh.positions[tr[1]] - mesh.positions[tr[0]],
                             mesh.positions[tr[2]] - mesh.positions[tr[0]]);
        Vec3 sum{};
        for (const Vec3& cn : mesh.corner_normals[f]) {
            if (!(std::abs(norm(cn) - 1) < 1e-9)) ++not_unit;
            sum += cn;
        }
        area += norm(n);
        if (dot(n, sum) > 0)
            ++agree;
        else
            folded_area += norm(n);
    }
    CHECK(not_unit == 0);
    if (!c.stiff_weights) {
        CHECK(agree > 0.99 * mesh.triangle_count());
    } else {
        // Known limitation, kept visible: where the weights squeeze a corner
        // into a tiny parameter region, the fan centre (the surface point at
        // the subpatch's parameter centre) falls outside the fan's boundary
        // and folds sliver triangles over; the planarity test on the control
        // net does not see it. They are a vanishing share of the area.
        CHECK(folded_area < 1e-3 * area);
    }
}

} // namespace

TEST_CASE("crack-free tessellation at the default tolerances", "[tessellation][heavy]") {
    for (const Case& c : cases()) check_crack_free(c, 1, true);
}

// 100x finer (up to about 1.5 million triangles each), one test case per model
// so that ctest runs them in parallel; every topology check and the geometric
// T-junction search.
#define CRACK_FREE_100X(file)                                                                      \
    TEST_CASE("crack-free tessellation at 100x finer tolerances: " file,                           \
              "[tessellation][fine][heavy]") {                                                     \
        check_crack_free(model_case(file), 100, true);                                             \
    }
CRACK_FREE_100X("models/teapot.json")
CRACK_FREE_100X("models/teacup.json")
CRACK_FREE_100X("models/teaspoon.json")
CRACK_FREE_100X("models/torus.json")
CRACK_FREE_100X("models/sphere.json")
CRACK_FREE_100X("cad/rounded_cube.json")
CRACK_FREE_100X("cad/torus.json")
CRACK_FREE_100X("models/torus_exact.json")
CRACK_FREE_100X("models/quarter_cylinder.json")
CRACK_FREE_100X("models/repeated_knot.json")
CRACK_FREE_100X("models/bilinear.json")
CRACK_FREE_100X("models/extreme_weights.json")

TEST_CASE("finer tolerances give more triangles and a smaller error bound",
          "[tessellation][heavy]") {
    const Model m = load_model(test::model_path("teapot.json"));
    const Tessellation coarse = tessellate(m, {});
    TessellationOptions fine_opt;
    fine_opt.eps1 = coarse.stats.eps1 / 16;
    fine_opt.eps2 = coarse.stats.eps2 / 16;
    const Tessellation fine = tessellate(m, fine_opt);
    CHECK(coarse.stats.eps1 == Approx(0.001 * d_max(m)));
    CHECK(coarse.stats.eps2 == Approx(0.02 * d_max(m)));
    // Deviation ~ h^2: 16x finer tolerances, about 4x finer steps each way.
    CHECK(fine.stats.triangles > 8 * coarse.stats.triangles);
    CHECK(fine.stats.max_error_bound < coarse.stats.max_error_bound / 4);
    CHECK(coarse.stats.patches == 32);
    CHECK(coarse.stats.collapsed_edges == 8);
    CHECK(coarse.stats.shared_edges == 52);
}

TEST_CASE("the naive curve-midpoint rule leaves cracks, the straight-midpoint rule none",
          "[tessellation][heavy]") {
    for (const char* name : {"torus.json", "rounded_cube.json"}) {
        const Model m = load_model(test::shared_dir() / "models/cad" / name);
        TessellationOptions opt;
        opt.crack_free = false;
        const Tessellation naive = tessellate(m, opt);
        opt.crack_free = true;
        const Tessellation good = tessellate(m, opt);
        INFO(name);
        // Same subdivision either way: only the vertex rule differs.
        CHECK(naive.stats.subpatches == good.stats.subpatches);
        const test::MeshReport rn = test::analyse_mesh(naive.mesh, naive.stats.d_max);
        const test::MeshReport rg = test::analyse_mesh(good.mesh, good.stats.d_max);
        // The curve midpoints leave the closed model with holes along every
        // edge split on one side only (Fig. 3's shaded section).
        CHECK(rn.border_edges > 0);
        CHECK(rg.border_edges == 0);
        CHECK(rg.t_junctions == 0);
    }
}

TEST_CASE("poles give one vertex and no degenerate triangles", "[tessellation][heavy]") {
    const Model m = load_model(test::model_path("teapot.json"));
    const Tessellation t = tessellate(m, {});
    int at_top = 0, at_bottom = 0;
    for (const Vec3& p : t.mesh.positions) {
        if (p == Vec3{0, 0, 3.15}) ++at_top;
        if (p == Vec3{0, 0, 0}) ++at_bottom;
    }
    CHECK(at_top == 1);
    CHECK(at_bottom == 1);
    // The pole's corner normals are limit normals: unit and (nearly) vertical.
    for (int f = 0; f < t.mesh.triangle_count(); ++f)
        for (int k = 0; k < 3; ++k)
            if (t.mesh.positions[t.mesh.triangles[f][k]] == Vec3{0, 0, 3.15})
                CHECK(std::abs(t.mesh.corner_normals[f][k].z) > 0.99);
}

TEST_CASE("corner uvs lie on the source surface's domain and map to the vertices",
          "[tessellation][heavy]") {
    const Model m = load_model(test::shared_dir() / "models/cad/torus.json");
    const Tessellation t = tessellate(m, {});
    double worst = 0;
    for (int f = 0; f < t.mesh.triangle_count(); f += 7)
        for (int k = 0; k < 3; ++k) {
            const BSplineSurface& s = m.surfaces[t.mesh.triangle_surface[f]];
            const auto uv = t.mesh.corner_uvs[f][k];
            REQUIRE(uv[0] >= s.u_min());
            REQUIRE(uv[0] <= s.u_max());
            REQUIRE(uv[1] >= s.v_min());
            REQUIRE(uv[1] <= s.v_max());
            worst = std::max(worst, distance(evaluate(s, uv[0], uv[1]).point,
                                             t.mesh.positions[t.mesh.triangles[f][k]]));
        }
    // Vertices moved onto straight edges stay within the error bound of the surface.
    CHECK(worst <= t.stats.max_error_bound);
}

TEST_CASE("certify = false leaves out the bound and nothing else", "[tessellation][heavy]") {
    const Model m = load_model(test::model_path("teapot.json"));
    TessellationOptions opt;
    const Tessellation with = tessellate(m, opt);
    opt.certify = false;
    const Tessellation without = tessellate(m, opt);
    CHECK(with.mesh.positions == without.mesh.positions);
    CHECK(with.mesh.triangles == without.mesh.triangles);
    CHECK(with.stats.subpatches == without.stats.subpatches);
    CHECK(with.stats.max_error_bound > 0);
    CHECK(std::isnan(without.stats.max_error_bound));
    for (const Subpatch& sp : without.subpatches) REQUIRE(std::isnan(sp.error_bound));
    // A tolerance is defined by the bound: it is computed whatever certify says.
    opt.tolerance = 0.01;
    const Tessellation tol = tessellate(m, opt);
    CHECK(tol.stats.max_error_bound > 0);
    CHECK(tol.stats.max_error_bound <= 0.01);
}
