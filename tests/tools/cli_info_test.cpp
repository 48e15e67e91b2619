// SPDX-License-Identifier: MIT
// The seamless program: help, info, and the error contract (one line, exit 2).
#include "test_util.h"

#include <catch2/catch.hpp>

using namespace seamless;

TEST_CASE("seamless --help and subcommand help", "[cli]") {
    auto r = test::run_cli("--help");
    CHECK(r.status == 0);
    CHECK_THAT(r.out, Catch::Contains("info"));
    auto i = test::run_cli("info --help");
    CHECK(i.status == 0);
    CHECK_THAT(i.out, Catch::Contains("MODEL"));
    auto none = test::run_cli("");
    CHECK(none.status == 2);
    // A mistyped command is named, with the commands there are, on one line.
    auto bogus = test::run_cli("tesselate");
    CHECK(bogus.status == 2);
    CHECK_THAT(bogus.err, Catch::StartsWith("error: unknown command 'tesselate'") &&
                              Catch::Contains("tessellate, convert, check, render, sweep"));
    CHECK(std::count(bogus.err.begin(), bogus.err.end(), '\n') == 1);
}

TEST_CASE("seamless info reports the teapot's 32 Bezier patches and d_max", "[cli]") {
    auto r = test::run_cli("info \"" + test::model_path("teapot.json").string() + "\"");
    CHECK(r.status == 0);
    CHECK_THAT(r.out, Catch::Contains("32 surfaces, 32 Bezier patches"));
    CHECK_THAT(r.out, Catch::Contains("d_max: 6.525"));
    auto j = test::run_cli("info --json \"" + test::model_path("torus.json").string() + "\"");
    CHECK(j.status == 0);
    CHECK_THAT(j.out, Catch::Contains("\"bezier_patches\": 48"));
}

TEST_CASE("seamless info on bad input: one line naming file and field, exit 2", "[cli]") {
    auto dir = test::scratch_dir("cli-info");
    test::write_file(dir / "bad.json",
                     R"({"version": 1, "surfaces": [{"degree": [3, 3], "size": [4, 4],
      "knots_u": [0,0,0,0,1,1,1,1], "knots_v": [0,0,0,0,1,1,1],
      "control_points": []}]})");
    auto r = test::run_cli("info \"" + (dir / "bad.json").string() + "\"");
    CHECK(r.status == 2);
    CHECK_THAT(r.err,
               Catch::StartsWith("error: ") &&
                   Catch::Contains("bad.json: surfaces[0].knots_v: expected 8 numbers, got 7"));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    auto missing = test::run_cli("info \"" + (dir / "missing.json").string() + "\"");
    CHECK(missing.status == 2);
    CHECK_THAT(missing.err, Catch::Contains("missing.json: cannot open file"));
}
