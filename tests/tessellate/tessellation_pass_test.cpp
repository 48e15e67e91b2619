// SPDX-License-Identifier: MIT
// TessellationPass (tessellation_pass.h): one pass without a tolerance is the
// whole tessellation; with one, split_again splits every subpatch the pass
// left above it, and the passes end below it.
#include "test_util.h"

#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>
#include <seamless/tessellate/tessellation_pass.h>

#include <catch2/catch.hpp>

#include <vector>

using namespace seamless;

namespace {

// The teapot's patches, tessellated on two threads.
struct Teapot {
    Model model = load_model(test::model_path("teapot.json"));
    std::vector<BezierPatch> patches = bezier_patches(model);
    TessellationOptions options = two_threads();
    static TessellationOptions two_threads() {
        TessellationOptions o;
        o.threads = 2;
        return o;
    }
};

} // namespace

TEST_CASE("TessellationPass: one pass without a tolerance, the triangles of tessellate()",
          "[tessellation_pass]") {
    const Teapot in;
    const Model& model = in.model;
    const std::vector<BezierPatch>& patches = in.patches;
    const TessellationOptions& o = in.options;
    TessellationPass pass(model, patches, o);
    const Tessellation t = pass.run(0, true);
    const Tessellation ref = tessellate(model, patches, o);
    CHECK(t.stats.passes == 1);
    CHECK(t.subpatches.size() == ref.subpatches.size());
    CHECK(t.mesh.triangles == ref.mesh.triangles);
    CHECK(t.trees.nodes.size() == ref.trees.nodes.size());
}

TEST_CASE("TessellationPass: split_again splits every subpatch left above the tolerance",
          "[tessellation_pass]") {
    Teapot in;
    in.options.tolerance = 0.001; // two passes (docs/results/tessellation.md)
    const TessellationOptions& o = in.options;
    const Model& model = in.model;
    const std::vector<BezierPatch>& patches = in.patches;
    TessellationPass pass(model, patches, o);
    Tessellation first = pass.run(0, false);
    REQUIRE(first.stats.above_tolerance > 0);
    CHECK(first.mesh.triangle_count() == 0); // another pass follows: no mesh
    std::vector<std::pair<int, ParamRect>> above;
    for (const Subpatch& sp : first.subpatches)
        if (splits_again(sp, first.stats.tolerance, o.max_depth))
            above.push_back({sp.patch, sp.rect});
    REQUIRE(!above.empty());
    pass.split_again(first);
    CHECK(first.subpatches.empty()); // its storage handed on to the next pass
    const Tessellation second = pass.run(1, true);
    int still = 0; // subpatches of the first pass's above the tolerance left whole
    for (const Subpatch& sp : second.subpatches)
        for (const auto& [patch, rect] : above) still += sp.patch == patch && sp.rect == rect;
    CHECK(still == 0);
    CHECK(second.mesh.triangle_count() > 0);
    CHECK(second.stats.max_error_bound > 0);
}
