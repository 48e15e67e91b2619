// SPDX-License-Identifier: MIT
// The fans' certified bounds (fan_certification.h): a bound kept for the next
// pass is found again by its ring, and one kept without its ring is computed
// again to the same value.
#include <tessellate/teapot_pass.h>

#include <seamless/tessellate/bounds/fan_certification.h>
#include <seamless/tessellate/fans/subpatch_ring.h>
#include <seamless/tessellate/fans/vertex_numbering.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace seamless;

TEST_CASE("bounds kept with their rings are found again, kept without computed again the same",
          "[fan_certification][heavy]") {
    const test::TeapotPass in;
    const auto& patches = in.patches;
    const int np = static_cast<int>(patches.size());
    const double tolerance = in.t.stats.tolerance;
    for (int threads : {1, 2}) {
        const SubpatchRings rings =
            collect_rings(patches, in.t.subpatches, in.reg, in.graph, true, threads);
        SubpatchRings numbered = rings;
        VertexRegistry vr;
        vr.patches = &patches;
        vr.match = &in.match;
        vr.edges = &in.reg;
        vr.alias = &in.graph.alias;
        vr.straight_segments = false;
        number_vertices(in.t.subpatches, in.leaf_start, in.graph, threads, vr, numbered);
        FanCertification fans(patches, 1.0, tolerance, 0, threads);
        std::vector<Subpatch> first = in.t.subpatches;
        const std::vector<char> fresh = fans.certify(numbered, vr.positions, nullptr, first);
        CHECK(std::count(fresh.begin(), fresh.end(), 1) == static_cast<long>(first.size()));
        // Rings kept for the even patches only.
        std::vector<char> compared(np, 0);
        for (int p = 0; p < np; p += 2) compared[p] = 1;
        fans.keep(numbered, vr.positions, in.leaf_start, fresh, &compared, first);
        std::vector<Subpatch> second = in.t.subpatches;
        const std::vector<char> again = fans.certify(numbered, vr.positions, nullptr, second);
        for (size_t i = 0; i < second.size(); ++i) {
            REQUIRE(std::isfinite(first[i].error_bound));
            CHECK(second[i].error_bound == first[i].error_bound);
            // Found by its ring on the even patches, computed on the odd ones.
            CHECK(again[i] == !compared[second[i].patch]);
        }
    }
}
