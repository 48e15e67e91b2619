// SPDX-License-Identifier: MIT
// The vertex numbering (vertex_numbering.h): the same numbers and positions
// whether a previous pass's positions (and keys) are taken or every point is
// evaluated.
#include <tessellate/teapot_pass.h>

#include <seamless/tessellate/fans/subpatch_ring.h>
#include <seamless/tessellate/fans/vertex_numbering.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

using namespace seamless;

TEST_CASE("vertices of rings kept from a previous pass keep their numbers and positions",
          "[vertex_numbering][heavy]") {
    const test::TeapotPass in;
    const auto& patches = in.patches;
    const auto& t = in.t;
    const auto& bm = in.match;
    const auto& reg = in.reg;
    const auto& g = in.graph;
    const auto& leaf_start = in.leaf_start;
    const int np = static_cast<int>(patches.size());
    const auto registry = [&] {
        VertexRegistry vr;
        vr.patches = &patches;
        vr.match = &bm;
        vr.edges = &reg;
        vr.alias = &g.alias;
        vr.straight_segments = false; // as with a tolerance
        return vr;
    };
    for (int threads : {1, 2}) {
        SubpatchRings fresh = collect_rings(patches, t.subpatches, reg, g, true, threads);
        VertexRegistry vr = registry();
        number_vertices(t.subpatches, leaf_start, g, threads, vr, fresh);
        // The mesh's vertices are these (the tessellation numbered them so),
        // but for the centres of subpatches written as two triangles.
        const auto quads = std::count_if(t.subpatches.begin(), t.subpatches.end(),
                                         [](const Subpatch& sp) { return sp.diagonal >= 0; });
        CHECK(vr.positions.size() == static_cast<size_t>(t.mesh.vertex_count() + quads));
        for (int every : {1, 2, 3}) {
            std::vector<char> same(np, 0);
            for (int p = 0; p < np; p += every) same[p] = 1;
            const PreviousRings previous{&fresh, &leaf_start, &leaf_start, &same, &vr.positions};
            SubpatchRings again =
                collect_rings(patches, t.subpatches, reg, g, true, threads, previous);
            VertexRegistry vr2 = registry();
            number_vertices(t.subpatches, leaf_start, g, threads, vr2, again, previous);
            REQUIRE(vr2.positions.size() == vr.positions.size());
            for (size_t v = 0; v < vr.positions.size(); ++v) {
                CHECK(vr2.positions[v].x == vr.positions[v].x);
                CHECK(vr2.positions[v].y == vr.positions[v].y);
                CHECK(vr2.positions[v].z == vr.positions[v].z);
            }
            REQUIRE(again.vertices.size() == fresh.vertices.size());
            for (size_t j = 0; j < fresh.vertices.size(); ++j)
                CHECK(again.vertices[j].vertex == fresh.vertices[j].vertex);
            CHECK(again.centre == fresh.centre);
            // The copied rings' keys are the ones computed afresh.
            REQUIRE(fresh.keys.size() == fresh.vertices.size());
            CHECK(again.keys == fresh.keys);
        }
    }
}
