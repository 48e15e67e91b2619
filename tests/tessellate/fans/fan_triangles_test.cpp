// SPDX-License-Identifier: MIT
// fan_normals (fan_triangles.h): each ring slot's normal is unit_normal at the
// slot's parameters approached from its subpatch's centre, and each centre's
// its own, bit for bit, on 1 and 2 threads, although a vertex's normal is
// computed once per patch where it is regular.
#include <tessellate/teapot_pass.h>

#include <seamless/spline/surface_point.h>
#include <seamless/tessellate/fans/fan_triangles.h>
#include <seamless/tessellate/fans/subpatch_ring.h>
#include <seamless/tessellate/fans/vertex_numbering.h>

#include <catch2/catch.hpp>

#include <vector>

using namespace seamless;

TEST_CASE("fan normals are unit_normal at every slot and centre", "[fan_triangles][heavy]") {
    const test::TeapotPass in;
    const auto& patches = in.patches;
    const auto& t = in.t;
    VertexRegistry vr;
    vr.patches = &patches;
    vr.match = &in.match;
    vr.edges = &in.reg;
    vr.alias = &in.graph.alias;
    vr.straight_segments = false; // as with a tolerance
    SubpatchRings rings = collect_rings(patches, t.subpatches, in.reg, in.graph, true, 2);
    number_vertices(t.subpatches, in.leaf_start, in.graph, 2, vr, rings);
    int shared = 0; // slots whose vertex is on another slot of the same patch
    for (int threads : {1, 2}) {
        const FanNormals n = fan_normals(patches, t.subpatches, in.leaf_start, rings, threads);
        REQUIRE(n.ring.size() == rings.vertices.size());
        REQUIRE(n.centre.size() == t.subpatches.size());
        std::vector<int> patch_of(vr.positions.size(), -1);
        for (size_t i = 0; i < t.subpatches.size(); ++i) {
            const Subpatch& sp = t.subpatches[i];
            const BezierPatch& b = patches[sp.patch];
            const double sc = 0.5 * (param_of(sp.rect.s0) + param_of(sp.rect.s1));
            const double tc = 0.5 * (param_of(sp.rect.t0) + param_of(sp.rect.t1));
            CHECK(test::same_bytes(n.centre[i], unit_normal(b, sc, tc, sc, tc)));
            for (int j = rings.start[i]; j < rings.start[i + 1]; ++j) {
                const RingVertex& v = rings.vertices[j];
                CHECK(test::same_bytes(n.ring[j], unit_normal(b, v.fs, v.ft, sc, tc)));
                if (threads == 1 && patch_of[v.vertex] == sp.patch) ++shared;
                patch_of[v.vertex] = sp.patch;
            }
        }
    }
    CHECK(shared > static_cast<int>(rings.vertices.size()) / 3); // the case is exercised
}
