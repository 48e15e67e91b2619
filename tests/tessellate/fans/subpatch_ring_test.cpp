// SPDX-License-Identifier: MIT
// The subpatches' rings (subpatch_ring.h), collected afresh and copied from a
// previous pass.
#include <tessellate/teapot_pass.h>

#include <seamless/tessellate/fans/subpatch_ring.h>

#include <catch2/catch.hpp>

#include <vector>

using namespace seamless;

namespace {

void check_same(const SubpatchRings& a, const SubpatchRings& b) {
    REQUIRE(a.start == b.start);
    REQUIRE(a.vertices.size() == b.vertices.size());
    for (size_t j = 0; j < a.vertices.size(); ++j) {
        const RingVertex &x = a.vertices[j], &y = b.vertices[j];
        CHECK((x.s == y.s && x.t == y.t && x.fs == y.fs && x.ft == y.ft && x.foreign == y.foreign &&
               x.vertex == y.vertex));
    }
    REQUIRE(a.centre_point.size() == b.centre_point.size());
    for (size_t i = 0; i < a.centre_point.size(); ++i) {
        CHECK(a.centre_point[i].x == b.centre_point[i].x);
        CHECK(a.centre_point[i].y == b.centre_point[i].y);
        CHECK(a.centre_point[i].z == b.centre_point[i].z);
    }
}

} // namespace

TEST_CASE("rings copied from a previous pass are the rings collected afresh",
          "[subpatch_ring][heavy]") {
    const test::TeapotPass in;
    const auto& patches = in.patches;
    const auto& t = in.t;
    const auto& reg = in.reg;
    const auto& g = in.graph;
    const auto& leaf_start = in.leaf_start;
    const int np = static_cast<int>(patches.size());
    for (int threads : {1, 2}) {
        const SubpatchRings fresh = collect_rings(patches, t.subpatches, reg, g, true, threads);
        // A previous pass whose numbering left its marks on the vertices.
        SubpatchRings old = fresh;
        for (RingVertex& v : old.vertices) v.vertex = 7;
        for (int every : {1, 2, 3}) {
            std::vector<char> same(np, 0);
            for (int p = 0; p < np; p += every) same[p] = 1;
            const PreviousRings previous{&old, &leaf_start, &leaf_start, &same};
            check_same(collect_rings(patches, t.subpatches, reg, g, true, threads, previous),
                       fresh);
        }
    }
}
