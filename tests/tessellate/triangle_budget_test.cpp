// SPDX-License-Identifier: MIT
// TessellationOptions::max_triangles: a tolerance that needs more triangles
// than the budget is refused with an InputError naming the model and the
// tolerance, a budget the mesh fits in changes nothing, and the CLI exits 2
// without an output file.
#include "test_util.h"
#include <seamless/base/error.h>
#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <string>

using namespace seamless;

TEST_CASE("max_triangles: the mesh's own count passes, one less is refused",
          "[tessellation][heavy]") {
    const Model m = load_model(test::model_path("teapot.json"));
    for (const double tolerance : {0.0, 0.01}) {
        TessellationOptions o;
        o.tolerance = tolerance;
        const Tessellation t = tessellate(m, o);
        o.max_triangles = t.stats.triangles;
        const Tessellation same = tessellate(m, o);
        CHECK(same.mesh.triangle_count() == t.mesh.triangle_count());
        o.max_triangles = t.stats.triangles - 1;
        try {
            tessellate(m, o);
            FAIL("a budget one below the mesh was accepted");
        } catch (const InputError& e) {
            CHECK(e.field() == (tolerance > 0 ? "tolerance" : "eps1, eps2"));
            CHECK(e.file() == m.source);
        }
    }
}

TEST_CASE("max_triangles: an absurd tolerance is refused, not run out of memory",
          "[tessellation][heavy]") {
    const Model m = load_model(test::model_path("teapot.json"));
    TessellationOptions o;
    o.tolerance = 1e-300;
    o.max_triangles = 200'000;
    try {
        (void)tessellate(m, o);
        FAIL("not refused");
    } catch (const TriangleBudgetError& e) {
        CHECK(e.limit() == 200'000);
        CHECK(e.field() == "tolerance");
        CHECK(std::string(e.what()).find("--") == std::string::npos); // no CLI flag
    }
}

TEST_CASE("seamless tessellate --max-triangles: exit 2, one line, no output", "[cli][heavy]") {
    const auto dir = test::scratch_dir("tessellate-budget");
    const auto out = dir / "t.off";
    const auto r = test::run_cli("tessellate \"" + test::model_path("teapot.json").string() +
                                     "\" --tolerance 1e-300 --max-triangles 100000 -o \"" +
                                     out.string() + "\"",
                                 "tessellate-budget");
    CHECK(r.status == 2);
    CHECK(r.err.find("teapot.json: tolerance: needs more than 100000 triangles") !=
          std::string::npos);
    CHECK(r.err.find("the --max-triangles limit") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(std::filesystem::exists(out));
}
