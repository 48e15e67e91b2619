// SPDX-License-Identifier: MIT
// Regression of issue 12, finding 5: a model whose control points are all one
// point (d_max = 0) made the tolerances 0, so no patch was ever planar and
// every one split to max_depth (3.2 GB, then "out of memory"). It is now an
// error at once; so is an extent below the rounding of the coordinates.
#include "test_util.h"

#include <seamless/base/error.h>
#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

using namespace seamless;

TEST_CASE("A zero-extent model is an error at once, not a split to max_depth",
          "[tessellate][hostile][cli]") {
    const auto dir = test::scratch_dir("zero-extent");
    test::write_file(dir / "point.json", test::bilinear_model("[[1,2,3],[1,2,3],[1,2,3],[1,2,3]]"));
    const auto r = test::run_cli("tessellate \"" + (dir / "point.json").string() + "\" -o \"" +
                                     (dir / "point.obj").string() + "\"",
                                 "zero-extent");
    CHECK(r.status == 2);
    CHECK_THAT(r.err,
               Catch::Contains("point.json: surfaces: every control point is the same point"));
    CHECK_FALSE(std::filesystem::exists(dir / "point.obj"));
    // Also with tolerances given, and through the library.
    const Model m =
        parse_model_json(test::bilinear_model("[[0,0,0],[0,0,0],[0,0,0],[0,0,0]]"), "zero.json");
    TessellationOptions opt;
    opt.eps1 = 0.1;
    opt.eps2 = 0.1;
    CHECK_THROWS_AS(tessellate(m, opt), InputError);
}

TEST_CASE("An extent below the rounding of the coordinates is an error at once",
          "[tessellate][hostile][heavy]") {
    // Extent 1e-6 at distance 1e6 from the origin: 1e-12 of the magnitude.
    const Model far = parse_model_json(
        test::bilinear_model("[[1e6,0,0],[1e6,1e-12,0],[1.000000000001e6,0,0],[1e6,0,1e-12]]"),
        "far.json");
    CHECK_THROWS_AS(tessellate(far), InputError);
    // 2^-20 of the magnitude still tessellates.
    const Model near = parse_model_json(
        test::bilinear_model("[[1e6,0,0],[1e6,1,0],[1000001,0,0],[1000001,1,1]]"), "near.json");
    CHECK(tessellate(near).mesh.triangle_count() > 0);
}
