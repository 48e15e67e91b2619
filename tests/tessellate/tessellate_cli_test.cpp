// SPDX-License-Identifier: MIT
// seamless tessellate: writes the mesh and statistics that match the library.
#include "seam_cases.h"
#include "test_util.h"

#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>

using namespace seamless;

TEST_CASE("seamless tessellate writes a mesh and --stats JSON", "[cli][heavy]") {
    const auto dir = test::scratch_dir("tessellate-cli");
    const auto model = test::model_path("teacup.json");
    const auto out = dir / "cup.obj", stats = dir / "cup.json";
    const auto r =
        test::run_cli("tessellate \"" + model.string() + "\" -o \"" + out.string() +
                          "\" --eps1 0.002 --eps2 0.01 --stats \"" + stats.string() + "\"",
                      "tessellate-cli");
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(r.out.find("triangles") != std::string::npos);
    CHECK(std::filesystem::file_size(out) > 0);
    std::ifstream in(stats);
    const auto js = nlohmann::json::parse(in);
    TessellationOptions opt;
    opt.eps1 = 0.002;
    opt.eps2 = 0.01;
    const Tessellation t = tessellate(load_model(model), opt);
    CHECK(js.at("triangles").get<int>() == t.stats.triangles);
    CHECK(js.at("vertices").get<int>() == t.stats.vertices);
    CHECK(js.at("subpatches").get<int>() == t.stats.subpatches);
    CHECK(js.at("patches").get<int>() == 26);
    CHECK(js.at("surfaces").get<int>() == 26);
    CHECK(js.at("eps1").get<double>() == 0.002);
    CHECK(js.at("eps2").get<double>() == 0.01);
    CHECK(js.at("max_error_bound").get<double>() == t.stats.max_error_bound);
    CHECK(js.at("seconds").get<double>() >= 0);
    // The phases' seconds (docs/formats.md), one field each.
    for (const char* phase : {"subdivision", "boundaries", "rings", "numbering", "bounds",
                              "normals", "fans", "orientation", "scaling"})
        CHECK(js.at("phase_seconds").at(phase).get<double>() >= 0);
}

TEST_CASE("seamless tessellate rejects a missing model with status 2", "[cli]") {
    const auto dir = test::scratch_dir("tessellate-cli-bad");
    const auto r =
        test::run_cli("tessellate /nonexistent/model.json -o \"" + (dir / "x.obj").string() + "\"",
                      "tessellate-cli-bad");
    CHECK(r.status == 2);
    CHECK_FALSE(std::filesystem::exists(dir / "x.obj"));
}

TEST_CASE("seamless tessellate --seam-tolerance stitches surfaces that meet within it",
          "[cli][heavy]") {
    const auto dir = test::scratch_dir("tessellate-cli-seam");
    const auto model = dir / "two_sheets.json";
    test::write_file(model, to_json(test::two_sheets(0.3, 1e-6)));
    auto seams = [&](const std::string& option) {
        const auto stats = dir / "stats.json";
        const auto r = test::run_cli("tessellate \"" + model.string() + "\" -o \"" +
                                         (dir / "out.obj").string() + "\" --stats \"" +
                                         stats.string() + "\" " + option,
                                     "tessellate-cli-seam");
        INFO(r.err);
        REQUIRE(r.status == 0);
        std::ifstream in(stats);
        return nlohmann::json::parse(in);
    };
    const auto apart = seams(""), stitched = seams("--seam-tolerance 1e-5");
    CHECK(apart.at("seams").get<int>() == 0);
    CHECK(stitched.at("seams").get<int>() > 0);
    CHECK(stitched.at("seam_tolerance").get<double>() == 1e-5);
    CHECK(stitched.at("seam_vertices").get<int>() > 0);
    const auto bad = test::run_cli("tessellate \"" + model.string() + "\" -o \"" +
                                       (dir / "x.obj").string() + "\" --seam-tolerance -1",
                                   "tessellate-cli-seam");
    CHECK(bad.status != 0);
}
