// SPDX-License-Identifier: MIT
// A requested deviation (TessellationOptions::tolerance): the certified bound
// is at most the tolerance, the measured deviation at most the bound and at
// least half of it, and the mesh stays crack-free without degenerate triangles.
#include "test_util.h"

#include <seamless/mesh/check/check.h>
#include <seamless/mesh/deviation/deviation.h>
#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

using namespace seamless;

namespace {

struct Case {
    const char* model;
    double relative; // tolerance / d_max
};

// Positions held by more than one vertex (once per extra vertex).
std::vector<Vec3> duplicate_positions(const TriangleMesh& mesh) {
    std::vector<Vec3> p = mesh.positions, out;
    std::sort(p.begin(), p.end(), [](Vec3 a, Vec3 b) {
        return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
    });
    for (size_t i = 1; i < p.size(); ++i)
        if (p[i] == p[i - 1]) out.push_back(p[i]);
    return out;
}

void check_tolerance(const Model& m, double relative, bool tight) {
    TessellationOptions opt;
    opt.tolerance = relative * d_max(m);
    const Tessellation t = tessellate(m, opt);
    const Deviation d = measure_deviation(m, t);
    INFO(m.source << " at " << relative << " d_max: " << t.stats.triangles << " triangles, bound "
                  << t.stats.max_error_bound << ", measured " << d.max() << " ("
                  << d.surface_to_mesh.max << " / " << d.mesh_to_surface.max << "), passes "
                  << t.stats.passes);
    CHECK(t.stats.tolerance == opt.tolerance);
    CHECK(t.stats.above_tolerance == 0);
    CHECK(t.stats.max_error_bound <= opt.tolerance);
    CHECK(d.max() <= t.stats.max_error_bound);
    if (tight) CHECK(t.stats.max_error_bound <= 2 * d.max());
    const CheckReport r = check_mesh(t.mesh);
    CHECK(r.degenerate_triangles.empty());
    const std::vector<Vec3> twins = duplicate_positions(t.mesh);
    if (std::string(m.source).find("teaspoon") == std::string::npos) {
        CHECK(twins.empty()); // welded as written: one vertex per point
        CHECK(r.cracks.empty());
        CHECK(r.t_junctions.empty());
        return;
    }
    // The teaspoon's bowl tip (y ~ 0.2) and handle end (y = -1) are free
    // boundaries around sliver holes of the model itself (shared/models/README.md,
    // docs/check.md): the 1% rule of check sees their facing borders as seams,
    // and their unmatched boundaries can meet at one point. Anywhere else a
    // crack, T-junction or second vertex at one point is the tessellator's.
    auto at_sliver = [](Vec3 p) { return p.y > 0.15 || p.y < -0.95; };
    for (const Crack& c : r.cracks) CHECK(at_sliver(c.location));
    for (const TJunction& j : r.t_junctions) CHECK(at_sliver(j.position));
    for (Vec3 p : twins) CHECK(at_sliver(p));
}

} // namespace

TEST_CASE("a requested tolerance is certified and met within a factor 2", "[tolerance][heavy]") {
    for (const char* name : {"teapot.json", "teacup.json", "teaspoon.json", "torus.json",
                             "sphere.json", "torus_exact.json"})
        for (double relative : {1e-2, 1e-3}) {
            const Model m = load_model(test::model_path(name));
            check_tolerance(m, relative, true);
        }
}

TEST_CASE("tolerances from 1e-1 to 1e-5 of d_max stay certified and crack-free",
          "[tolerance][heavy]") {
    const Model sphere = load_model(test::model_path("sphere.json"));
    for (double relative : {1e-1, 1e-4, 1e-5}) check_tolerance(sphere, relative, false);
    // The fuselage, whose cylinder rulings are straight but unevenly
    // parametrised, kept its bound above any tolerance until the subdivision
    // split by second derivatives.
    const Model teapot = load_model(test::model_path("teapot.json"));
    for (double relative : {1e-1, 1e-2, 1e-3}) check_tolerance(teapot, relative, false);
    const Model fuselage = load_model(test::model_path("cad/bug28366_fuselage.json"));
    for (double relative : {1e-2, 1e-3, 1e-4}) check_tolerance(fuselage, relative, false);
}

// Where a pass left subpatches above the tolerance (docs/results/tessellation.md,
// before the fix): neighbours one level apart across the teapot's patch
// edges (a finer corner on the coarser side's straight segment, which phi may
// not move across a patch edge), and rows of subpatches accepted just below
// the tolerance whose final bound, with a neighbour's vertex on a side, came
// out a few percent above it (teacup, fuselage). The pass loop must end with
// every subpatch within the tolerance.
TEST_CASE("the tolerance is reached where earlier passes left subpatches above it",
          "[tolerance][heavy]") {
    const Model teapot = load_model(test::model_path("teapot.json"));
    check_tolerance(teapot, 1e-4, false);
    const Model teacup = load_model(test::model_path("teacup.json"));
    check_tolerance(teacup, 0.001 / d_max(teacup), false);
    const Model fuselage = load_model(test::model_path("cad/bug28366_fuselage.json"));
    check_tolerance(fuselage, 0.002 / d_max(fuselage), false);
}

// 1e-5 d_max on the whole teapot is over a million triangles (half a minute);
// its knob and lid (patches 20 to 27: the knob's pole, and the lid's seams
// where neighbours ended a level apart) are the hard part, in seconds.
TEST_CASE("the teapot's lid and knob at 1e-5 d_max: certified, welded, no T-junctions",
          "[tolerance][heavy]") {
    const Model teapot = load_model(test::model_path("teapot.json"));
    const std::vector<BezierPatch> all = bezier_patches(teapot);
    REQUIRE(all.size() == 32);
    const std::vector<BezierPatch> lid(all.begin() + 20, all.begin() + 28);
    TessellationOptions opt;
    opt.tolerance = 1e-5 * d_max(teapot);
    const Tessellation t = tessellate(teapot, lid, opt);
    INFO(t.stats.triangles << " triangles, bound " << t.stats.max_error_bound << ", passes "
                           << t.stats.passes);
    CHECK(t.stats.above_tolerance == 0);
    CHECK(t.stats.max_error_bound <= opt.tolerance);
    // Mesh -> surface measured (surface -> mesh would sample the patches left out).
    const Deviation d = measure_deviation(teapot, t.mesh);
    INFO("mesh -> surface " << d.mesh_to_surface.max);
    CHECK(d.mesh_to_surface.samples > 5 * t.stats.triangles);
    CHECK(d.mesh_to_surface.max <= t.stats.max_error_bound);
    const CheckReport r = check_mesh(t.mesh);
    CHECK(duplicate_positions(t.mesh).empty());
    CHECK(r.degenerate_triangles.empty());
    CHECK(r.cracks.empty());
    CHECK(r.t_junctions.empty());
    CHECK(r.non_manifold_edges.empty());
}

TEST_CASE("finer tolerances give more triangles and smaller bounds", "[tolerance]") {
    const Model m = load_model(test::model_path("teacup.json"));
    TessellationOptions coarse, fine;
    coarse.tolerance = 1e-2 * d_max(m);
    fine.tolerance = 1e-3 * d_max(m);
    const Tessellation a = tessellate(m, coarse), b = tessellate(m, fine);
    CHECK(b.stats.triangles > 4 * a.stats.triangles);
    CHECK(b.stats.max_error_bound < a.stats.max_error_bound / 4);
    // No planarity test unless asked for.
    CHECK(a.stats.eps1 == 0);
    CHECK(a.stats.eps2 == 0);
}
