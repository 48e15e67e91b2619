// SPDX-License-Identifier: MIT
// TessellationOptions::progress (pass_progress.h): fractions in [0, 1] that
// end at 1, a later pass above 0.9, from any thread; the mesh does not
// depend on whether progress is reported.
#include "test_util.h"

#include <seamless/model/model.h>
#include <seamless/tessellate/pass_progress.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <mutex>
#include <vector>

using namespace seamless;

TEST_CASE("PassProgress: the first pass spans 0..0.9, each later one half of what is left",
          "[tessellation]") {
    std::vector<double> seen;
    const std::function<void(double)> report = [&](double f) { seen.push_back(f); };
    PassProgress(report, 0).at(0);
    PassProgress(report, 0).at(1);
    PassProgress(report, 1).at(0);
    PassProgress(report, 1).at(1);
    PassProgress(report, 2).at(0);
    PassProgress(report, 2).within(0, 0.5, 3, 6); // a quarter of pass 2
    PassProgress(report, 2).at(1);
    const std::vector<double> want{0, 0.9, 0.9, 0.95, 0.95, 0.95 + 0.025 / 4, 0.975};
    REQUIRE(seen.size() == want.size());
    for (size_t i = 0; i < want.size(); ++i) CHECK(seen[i] == Approx(want[i]));
    const std::function<void(double)> none;
    PassProgress(none, 0).at(0.5); // nothing to call: no crash
    CHECK_FALSE(static_cast<bool>(PassProgress(none, 0)));
}

TEST_CASE("TessellationOptions::progress: from 0 to 1 over the passes, the same mesh",
          "[tessellation][heavy]") {
    const Model m = load_model(test::model_path("teapot.json"));
    TessellationOptions o;
    o.tolerance = 0.001; // two passes on the teapot
    o.threads = 2;
    o.patch_trees = false;
    const Tessellation quiet = tessellate(m, o);
    std::mutex mutex;
    std::vector<double> seen;
    o.progress = [&](double f) {
        std::lock_guard<std::mutex> lock(mutex);
        seen.push_back(f);
    };
    const Tessellation t = tessellate(m, o);
    REQUIRE(t.stats.passes >= 2);
    CHECK(t.mesh.positions == quiet.mesh.positions);
    CHECK(t.mesh.triangles == quiet.mesh.triangles);
    REQUIRE(seen.size() > 20); // within the subdivision and the bounds, not per phase only
    CHECK(std::all_of(seen.begin(), seen.end(), [](double f) { return f >= 0 && f <= 1; }));
    CHECK(seen.back() == 1.0);
    CHECK(std::count_if(seen.begin(), seen.end(), [](double f) { return f < 0.9; }) > 10);
    CHECK(std::count_if(seen.begin(), seen.end(), [](double f) { return f > 0.9 && f < 1; }) > 0);
}
