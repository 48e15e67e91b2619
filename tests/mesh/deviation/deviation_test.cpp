// SPDX-License-Identifier: MIT
// Measured deviation (lib/mesh/deviation/deviation.h) against the a-priori error bound.
#include "tessellate/seam_cases.h"
#include "test_util.h"

#include <seamless/mesh/deviation/deviation.h>
#include <seamless/mesh/deviation/sweep.h>
#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

#include <sstream>

using namespace seamless;

namespace {

Tessellation at_factor(const Model& m, double factor) {
    const PlanarityTolerances e = paper_tolerances(d_max(m), factor);
    TessellationOptions opt;
    opt.eps1 = e.eps1;
    opt.eps2 = e.eps2;
    return tessellate(m, opt);
}

void check_within_bound(const Model& m, const Tessellation& t, const Deviation& d) {
    INFO(m.source << ": " << t.stats.triangles << " triangles, bound " << t.stats.max_error_bound
                  << ", surface->mesh " << d.surface_to_mesh.max << ", mesh->surface "
                  << d.mesh_to_surface.max << ", same parameter " << d.mesh_same_parameter.max);
    CHECK(d.surface_to_mesh.samples > 0);
    CHECK(d.mesh_to_surface.samples > 0);
    CHECK(d.mesh_same_parameter.samples == d.mesh_to_surface.samples);
    CHECK(d.surface_to_mesh.max <= t.stats.max_error_bound);
    CHECK(d.mesh_to_surface.max <= t.stats.max_error_bound);
    // Newton only improves on the same-parameter distance.
    CHECK(d.mesh_to_surface.max <= d.mesh_same_parameter.max);
    CHECK(d.mesh_to_surface.rms <= d.mesh_same_parameter.rms);
    CHECK(d.surface_to_mesh.rms <= d.surface_to_mesh.max);
    // The measurement is not vacuous: a curved model deviates measurably.
    CHECK(d.max() > 1e-3 * t.stats.max_error_bound);
}

} // namespace

TEST_CASE("measured deviation stays below the error bound", "[deviation][heavy]") {
    for (const char* name : {"teapot.json", "torus.json", "torus_exact.json", "bilinear.json"}) {
        const Model m = load_model(test::model_path(name));
        for (double factor : {10.0, 1.0}) {
            const Tessellation t = at_factor(m, factor);
            check_within_bound(m, t, measure_deviation(m, t));
        }
    }
}

TEST_CASE("finer tolerances measure a smaller deviation", "[deviation][heavy]") {
    const Model m = load_model(test::model_path("teapot.json"));
    const Tessellation coarse = at_factor(m, 1), fine = at_factor(m, 0.1);
    const Deviation dc = measure_deviation(m, coarse), df = measure_deviation(m, fine);
    CHECK(df.max() < dc.max() / 4);
    CHECK(df.surface_to_mesh.rms < dc.surface_to_mesh.rms / 4);
}

TEST_CASE("the result does not depend on the thread count", "[deviation][heavy]") {
    const Model m = load_model(test::model_path("torus.json"));
    const Tessellation t = at_factor(m, 1);
    DeviationOptions one, two;
    one.threads = 1;
    two.threads = 3;
    const Deviation a = measure_deviation(m, t, one), b = measure_deviation(m, t, two);
    CHECK(a.surface_to_mesh.max == b.surface_to_mesh.max);
    CHECK(a.surface_to_mesh.rms == b.surface_to_mesh.rms);
    CHECK(a.mesh_to_surface.rms == b.mesh_to_surface.rms);
    CHECK(a.mesh_same_parameter.max == b.mesh_same_parameter.max);
}

TEST_CASE("a flat patch deviates by rounding only; Newton finds it, the parameter does not",
          "[deviation]") {
    // A bicubic patch in the plane z = 1 over the square [0,3]^2 with straight
    // boundaries but a non-uniform parametrisation (inner control points moved
    // within the plane): the surface is exactly the square.
    std::ostringstream pts;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const bool inner_i = i == 1 || i == 2, inner_j = j == 1 || j == 2;
            double x = i, y = j;
            if (inner_i) x += 0.6; // along u, also on the boundary rows j = 0, 3
            if (inner_j) y -= 0.5;
            pts << (i + j > 0 ? "," : "") << "[" << x << "," << y << ",1]";
        }
    const Model m = parse_model_json(
        R"({"version":1,"surfaces":[{"name":"flat","degree":[3,3],"size":[4,4],)"
        R"("knots_u":[0,0,0,0,1,1,1,1],"knots_v":[0,0,0,0,1,1,1,1],"control_points":[)" +
            pts.str() + "]}]}",
        "flat.json");
    // Planar at once (every control point in the plane, boundaries straight):
    // one subpatch, a fan of four triangles.
    const Tessellation t = tessellate(m, {});
    REQUIRE(t.stats.triangles == 4);
    const Deviation d = measure_deviation(m, t);
    INFO("same parameter " << d.mesh_same_parameter.max);
    CHECK(d.surface_to_mesh.max < 1e-12);
    CHECK(d.mesh_to_surface.max < 1e-9);
    // The mesh's (u,v) is the piecewise linear interpolant, not the patch's
    // parametrisation: the same-parameter distance is in-plane and not ~0...
    CHECK(d.mesh_same_parameter.max > 1e-6);
    // ...and the bound, which is geometric, does not count it.
    CHECK(t.stats.max_error_bound < d.mesh_same_parameter.max);
    CHECK(d.max() <= t.stats.max_error_bound);
}

TEST_CASE("a sweep scales both tolerances and stops at the triangle limit", "[deviation][heavy]") {
    const Model m = load_model(test::model_path("torus.json"));
    SweepOptions opt;
    opt.first_decade = 1;
    opt.decades = 6;
    opt.steps_per_decade = 1;
    opt.max_triangles = 20'000;
    std::vector<double> seen; // SweepOptions::on_row: each row once, in order
    opt.on_row = [&](const SweepRow& r) { seen.push_back(r.factor); };
    const std::vector<SweepRow> rows = sweep_tolerances(m, opt);
    REQUIRE(rows.size() >= 2);
    REQUIRE(seen.size() == rows.size());
    for (size_t i = 0; i < rows.size(); ++i) CHECK(seen[i] == rows[i].factor);
    CHECK(rows.size() < 7);
    CHECK(rows[0].factor == Approx(10));
    CHECK(rows[1].factor == Approx(1));
    CHECK(rows[0].tess.eps1 == Approx(0.01 * d_max(m)));
    CHECK(rows[0].tess.eps2 == Approx(0.2 * d_max(m)));
    for (size_t i = 0; i < rows.size(); ++i) {
        CHECK(rows[i].within_bound());
        CHECK(rows[i].tess.triangles <= opt.max_triangles);
        if (i > 0) CHECK(rows[i].tess.triangles >= rows[i - 1].tess.triangles);
    }
}

TEST_CASE("measured deviation stays below the error bound across seams", "[deviation][heavy]") {
    // Seam vertices of the other side sit at their projected parameter (and,
    // within a gap, off this side's surface): the bound must still hold.
    for (const test::SeamCase& c : test::closed_seam_cases()) {
        TessellationOptions opt;
        opt.seam_tolerance = c.seam_tolerance;
        const Tessellation t = tessellate(c.model, opt);
        check_within_bound(c.model, t, measure_deviation(c.model, t));
    }
}
