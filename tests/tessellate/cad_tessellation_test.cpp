// SPDX-License-Identifier: MIT
// The CAD files of data/models/cad, read through STEP/IGES, tessellate to the
// shapes their README describes, at the default tolerances and 100x finer:
// closed with the right Euler characteristic, one open shell with one border
// loop, separate sheets, and no crack along a seam two surfaces share.
// The tire's surfaces (bare IGES 128 entities, no faces) are oriented
// inconsistently in the file; the tessellation turns them consistent
// (surface_orientation.h); tests/tools/cli_cad_test.cpp runs `check` on it.
#include "mesh_properties.h"
#include "test_util.h"

#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

#include <array>
#include <map>
#include <numeric>

using namespace seamless;

namespace {

struct Find {
    std::vector<int> parent;
    explicit Find(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
    int operator()(int a) {
        while (parent[a] != a) a = parent[a] = parent[parent[a]];
        return a;
    }
    void join(int a, int b) { parent[(*this)(a)] = (*this)(b); }
};

// Shells (triangles joined through shared edges), border edges, border loops
// (border edges joined through shared vertices) and cracks: border edges
// whose midpoint lies on another border edge, i.e. two sides of a seam left
// apart.
struct Shape {
    int shells = 0, border_edges = 0, border_loops = 0, cracks = 0;
    std::vector<long long> shell_euler; // V - E + F of each shell on its own
};

Shape shape_of(const TriangleMesh& m, double d_max) {
    Shape s;
    std::map<std::pair<int, int>, std::vector<int>> edge_triangles;
    for (int f = 0; f < m.triangle_count(); ++f)
        for (int k = 0; k < 3; ++k) {
            const int a = m.triangles[f][k], b = m.triangles[f][(k + 1) % 3];
            edge_triangles[{std::min(a, b), std::max(a, b)}].push_back(f);
        }
    Find shells(m.triangles.size()), loops(m.positions.size());
    std::vector<std::pair<int, int>> border;
    for (const auto& [e, tris] : edge_triangles) {
        for (size_t k = 1; k < tris.size(); ++k) shells.join(tris[k], tris[0]);
        if (tris.size() == 1) {
            border.push_back(e);
            loops.join(e.first, e.second);
        }
    }
    std::map<int, std::array<long long, 3>> vef; // shell root -> V, E, F
    std::map<std::pair<int, int>, char> shell_vertex;
    for (int f = 0; f < m.triangle_count(); ++f) {
        s.shells += shells(f) == f;
        ++vef[shells(f)][2];
        for (int v : m.triangles[f])
            if (!shell_vertex[{shells(f), v}]++) ++vef[shells(f)][0];
    }
    for (const auto& [e, tris] : edge_triangles) ++vef[shells(tris[0])][1];
    for (const auto& [root, n] : vef) s.shell_euler.push_back(n[0] - n[1] + n[2]);
    s.border_edges = static_cast<int>(border.size());
    std::vector<char> root(m.positions.size(), 0);
    for (const auto& e : border) root[loops(e.first)] = 1;
    s.border_loops = static_cast<int>(std::count(root.begin(), root.end(), 1));
    const double tol = 1e-7 * d_max;
    for (const auto& e : border) {
        const Vec3 mid = 0.5 * (m.positions[e.first] + m.positions[e.second]);
        for (const auto& o : border) {
            if (o == e) continue;
            const Vec3 a = m.positions[o.first], d = m.positions[o.second] - a;
            const double t = std::clamp(dot(mid - a, d) / dot(d, d), 0.0, 1.0);
            if (distance(mid, a + t * d) <= tol) {
                ++s.cracks;
                break;
            }
        }
    }
    return s;
}

struct Result {
    test::MeshReport report;
    Shape shape;
};

Result tessellate_cad(const std::string& name, double factor,
                      TrimmedFaces trimmed = TrimmedFaces::refuse, bool oriented = true) {
    ModelLoadOptions load;
    load.trimmed = trimmed;
    const Model m = load_model(test::model_path("cad/" + name), load);
    TessellationOptions opt;
    opt.eps1 = 0.001 * d_max(m) / factor;
    opt.eps2 = 0.02 * d_max(m) / factor;
    opt.certify = false; // topology only: the bound is error_bound_test's
    const Tessellation t = tessellate(m, opt);
    REQUIRE(t.mesh.triangle_count() > 0);
    Result r{test::analyse_mesh(t.mesh, t.stats.d_max), shape_of(t.mesh, t.stats.d_max)};
    INFO(name << " at 1/" << factor << " of the default tolerances: " << t.stats.triangles
              << " triangles; " << r.report.example);
    CHECK(r.report.duplicate_positions == 0);
    CHECK(r.report.zero_area == 0);
    CHECK(r.report.t_junctions == 0);
    CHECK(r.report.nonmanifold_edges == 0);
    if (oriented) CHECK(r.report.misoriented_edges == 0);
    return r;
}

void check_closed(const std::string& name, long long euler) {
    for (double factor : {1.0, 100.0}) {
        INFO(name << " at 1/" << factor);
        const Result r = tessellate_cad(name, factor);
        CHECK(r.shape.shells == 1);
        CHECK(r.report.border_edges == 0);
        CHECK(r.report.euler() == euler);
    }
}

} // namespace

TEST_CASE("torus.igs tessellates closed, Euler characteristic 0", "[tessellation][cad][heavy]") {
    check_closed("torus.igs", 0);
}

TEST_CASE("rounded_cube.iges (seams within 7.8e-15) tessellates closed, Euler characteristic 2",
          "[tessellation][cad][heavy]") {
    check_closed("rounded_cube.iges", 2);
}

TEST_CASE("bug28366_fuselage.stp (pole, knife edge) tessellates closed, Euler characteristic 2",
          "[tessellation][cad][heavy]") {
    check_closed("bug28366_fuselage.stp", 2);
}

TEST_CASE("sunglasses_lens.igs is one open shell with one border loop",
          "[tessellation][cad][heavy]") {
    for (double factor : {1.0, 100.0}) {
        INFO("1/" << factor);
        const Result r = tessellate_cad("sunglasses_lens.igs", factor);
        CHECK(r.shape.shells == 1);
        CHECK(r.shape.border_loops == 1);
        CHECK(r.shape.cracks == 0);
        CHECK(r.report.euler() == 1); // a disc
    }
}

TEST_CASE("splinecage.stp tessellates as four separate sheets", "[tessellation][cad][heavy]") {
    for (double factor : {1.0, 100.0}) {
        INFO("1/" << factor);
        const Result r = tessellate_cad("splinecage.stp", factor);
        CHECK(r.shape.shells == 4);
        // Each sheet is a disc; they touch only at corner points, with no crack.
        CHECK(r.shape.shell_euler == std::vector<long long>(4, 1));
        CHECK(r.shape.cracks == 0);
    }
}

TEST_CASE("tire.iges --skip-trimmed: no crack along a seam its surfaces share",
          "[tessellation][cad][heavy]") {
    for (double factor : {1.0, 100.0}) {
        INFO("1/" << factor);
        const Result r = tessellate_cad("tire.iges", factor, TrimmedFaces::skip, false);
        CHECK(r.shape.cracks == 0);
        CHECK(r.shape.border_edges > 0); // the tire is open where its trimmed faces were
    }
}

TEST_CASE("generated box, sphere and torus STEP files tessellate closed",
          "[tessellation][cad][heavy]") {
    check_closed("generated/box.step", 2);
    check_closed("generated/sphere.step", 2);
    check_closed("generated/torus.step", 0);
}

TEST_CASE("pyocc_surf114.igs (folded C0 surfaces) meets the bench's tolerance and angle",
          "[tessellation][cad][heavy]") {
    // Near its folds a patch's normal turns a quarter turn along straight
    // rulings and at points inside it: the angle criterion halves a rejected
    // fan along its longer sides and leaves fans within D / 8 to the
    // tolerance, so the mesh stays of the size the tolerance alone needs.
    const Model m = load_model(test::shared_dir() / "models/cad-corpus/pyocc_surf114.igs");
    TessellationOptions opt;
    opt.tolerance = 1e-3 * d_max(m);
    opt.certify = false;
    const int alone = tessellate(m, opt).mesh.triangle_count();
    opt.angle = 0.5;
    opt.max_triangles = 500'000;
    const Tessellation t = tessellate(m, opt);
    INFO(alone << " triangles for the tolerance alone, " << t.mesh.triangle_count()
               << " with the angle");
    CHECK(t.mesh.triangle_count() < 4 * alone);
    const test::MeshReport r = test::analyse_mesh(t.mesh, t.stats.d_max);
    CHECK(r.zero_area == 0);
    CHECK(r.t_junctions == 0);
    CHECK(r.nonmanifold_edges == 0);
}
