// SPDX-License-Identifier: MIT
// The vertex numbering (vertex_numbering.h): the same numbers and positions
// whether a previous pass's positions are taken or every point is evaluated.
#include "test_util.h"

#include <seamless/model/model.h>
#include <seamless/tessellate/edge_graph.h>
#include <seamless/tessellate/subpatch_ring.h>
#include <seamless/tessellate/tessellation.h>
#include <seamless/tessellate/vertex_numbering.h>

#include <catch2/catch.hpp>

#include <vector>

using namespace seamless;

TEST_CASE("vertices of rings kept from a previous pass keep their numbers and positions",
          "[vertex_numbering]") {
    const Model m = load_model(test::model_path("teapot.json"));
    const auto patches = bezier_patches(m);
    TessellationOptions o;
    o.tolerance = 0.01;
    const Tessellation t = tessellate(m, patches, o);
    const BoundaryMatch bm = match_boundaries(patches, t.stats.seam_tolerance);
    const EdgeRegistry reg = build_edge_registry(bm, t.subpatches, 2);
    const EdgeGraph g = build_edge_graph(patches, bm, reg, t.stats.seam_tolerance);
    const int np = static_cast<int>(patches.size());
    std::vector<int> leaf_start(np + 1, 0);
    for (const Subpatch& sp : t.subpatches) ++leaf_start[sp.patch + 1];
    for (int p = 0; p < np; ++p) leaf_start[p + 1] += leaf_start[p];
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
        // The mesh's vertices are these (the tessellation numbered them so).
        CHECK(vr.positions.size() == static_cast<size_t>(t.mesh.vertex_count()));
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
        }
    }
}
