// SPDX-License-Identifier: MIT
// Shared boundaries and the crack-free vertex rule (paper section 6, Fig. 3).
#include "test_util.h"
#include <tessellate/teapot_pass.h>

#include <seamless/model/model.h>
#include <seamless/tessellate/seams/shared_edges.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <vector>

using namespace seamless;

TEST_CASE("teaset boundaries match as the model notes describe", "[shared_edges]") {
    // shared/models/README.md: teapot 52 shared pairs (4 reversed, body/bottom),
    // 8 collapsed edges; teacup 46; teaspoon 28 (its near pairs are no seams).
    struct Expect {
        const char* name;
        int shared, reversed, collapsed;
    };
    for (Expect e : {Expect{"teapot.json", 52, 4, 8}, Expect{"teacup.json", 46, 0, 0},
                     Expect{"teaspoon.json", 28, 0, 0}}) {
        const Model m = load_model(test::model_path(e.name));
        const auto patches = bezier_patches(m);
        const BoundaryMatch bm = match_boundaries(patches, 1e-12 * d_max(m));
        INFO(e.name);
        CHECK(bm.shared_edges == e.shared);
        CHECK(bm.collapsed_edges == e.collapsed);
        int reversed = 0;
        for (char r : bm.edge_reversed) reversed += r;
        CHECK(reversed == e.reversed);
        for (int g = 0; g < static_cast<int>(bm.group_size.size()); ++g)
            CHECK(bm.group_size[g] <= 2);
    }
}

TEST_CASE("a periodic torus matches its own seams and welds its corners", "[shared_edges]") {
    const Model m = load_model(test::shared_dir() / "models/cad/torus.json");
    const auto patches = bezier_patches(m);
    const BoundaryMatch bm = match_boundaries(patches, 1e-12 * d_max(m));
    // Closed: every patch edge is shared with exactly one other.
    CHECK(bm.shared_edges * 2 == 4 * static_cast<int>(patches.size()));
    // Each welded corner is shared by four patch corners.
    std::vector<int> count(bm.corner_root.size(), 0);
    for (int r : bm.corner_root) ++count[r];
    for (size_t c = 0; c < count.size(); ++c)
        if (bm.corner_root[c] == static_cast<int>(c)) CHECK(count[c] == 4);
}

TEST_CASE("vertices inside a coarse side lie on its straight segment (Q0 = (Q1+Q2)/2)",
          "[shared_edges][heavy]") {
    const Model m = load_model(test::model_path("teapot.json"));
    const auto patches = bezier_patches(m);
    const Tessellation t = tessellate(m, patches, {});
    const BoundaryMatch bm = match_boundaries(patches, 1e-12 * t.stats.d_max);
    const EdgeRegistry reg = build_edge_registry(bm, t.subpatches);
    // Rebuild the vertex table: positions must come out bit-identical.
    VertexRegistry vr;
    vr.patches = &patches;
    vr.match = &bm;
    vr.edges = &reg;
    int on_segments = 0;
    std::vector<int> inside;
    for (const Subpatch& sp : t.subpatches)
        for (int k = 0; k < 4; ++k) {
            const SideOnLine side = side_on_line(reg, bm, sp.patch, sp.rect, k);
            inside.clear();
            points_inside(reg, side, inside);
            if (inside.empty()) continue;
            const ParamRect& r = sp.rect;
            const int cs[5] = {r.s0, r.s1, r.s1, r.s0, r.s0},
                      ct[5] = {r.t0, r.t0, r.t1, r.t1, r.t0};
            const Vec3 q1 = vr.positions[vertex_at(vr, sp.patch, cs[k], ct[k])];
            const Vec3 q2 = vr.positions[vertex_at(vr, sp.patch, cs[k + 1], ct[k + 1])];
            for (int x : inside) {
                if (side.reversed) x = kParamOne - x;
                const bool along_s = k % 2 == 0;
                const int s = along_s ? x : cs[k], tt = along_s ? ct[k] : x;
                const Vec3 q0 = vr.positions[vertex_at(vr, sp.patch, s, tt)];
                const double w = along_s ? double(x - cs[k]) / (cs[k + 1] - cs[k])
                                         : double(x - ct[k]) / (ct[k + 1] - ct[k]);
                CHECK(distance(q0, lerp(q1, q2, w)) <= 1e-14 * t.stats.d_max);
                ++on_segments;
            }
        }
    CHECK(on_segments > 0); // the teapot does have T-junctions to resolve
    // Same positions as the tessellation's (every vertex there was made the same way).
    for (int v = 0; v < static_cast<int>(vr.positions.size()); ++v) {
        bool found = false;
        for (const Vec3& p : t.mesh.positions)
            if (p == vr.positions[v]) {
                found = true;
                break;
            }
        CHECK(found);
        if (v > 200) break;
    }
}

namespace {

// The segments of the line a side lies on, as a set (line numbers aside).
std::vector<std::array<int, 3>> segments_of(const EdgeRegistry& reg, int line) {
    std::vector<std::array<int, 3>> out;
    for (int i = reg.offsets[line]; i < reg.offsets[line + 1]; ++i)
        out.push_back({reg.segments[i].side, reg.segments[i].a, reg.segments[i].b});
    return out;
}

} // namespace

TEST_CASE("the edge registry is the same for any thread count and subpatch order",
          "[shared_edges][heavy]") {
    const test::TeapotPass in;
    const auto& t = in.t;
    const auto& bm = in.match;
    const EdgeRegistry one = build_edge_registry(bm, t.subpatches, 1);
    const EdgeRegistry two = build_edge_registry(bm, t.subpatches, 2);
    CHECK(one.offsets == two.offsets);
    CHECK(one.interior_keys == two.interior_keys);
    CHECK(one.interior_lines == two.interior_lines);
    REQUIRE(one.segments.size() == two.segments.size());
    for (size_t i = 0; i < one.segments.size(); ++i) {
        CHECK(one.segments[i].a == two.segments[i].a);
        CHECK(one.segments[i].b == two.segments[i].b);
        CHECK(one.segments[i].side == two.segments[i].side);
    }
    // Subpatches in reverse order (patches interleaved with nothing in order):
    // every side on the same line content, found by side_on_line too.
    std::vector<Subpatch> reversed(t.subpatches.rbegin(), t.subpatches.rend());
    const EdgeRegistry rev = build_edge_registry(bm, reversed, 2);
    REQUIRE(one.sides.size() == 4 * t.subpatches.size());
    REQUIRE(rev.sides.size() == one.sides.size());
    const size_t n = t.subpatches.size();
    for (size_t i = 0; i < n; ++i) {
        const Subpatch& sp = t.subpatches[i];
        for (int k = 0; k < 4; ++k) {
            const SideOnLine& a = one.sides[4 * i + k];
            const SideOnLine& b = rev.sides[4 * (n - 1 - i) + k];
            const SideOnLine c = side_on_line(one, bm, sp.patch, sp.rect, k);
            CHECK(a.line == c.line);
            CHECK((a.a == b.a && a.b == b.b && a.side == b.side && a.reversed == b.reversed));
            CHECK((a.line < 0) == (b.line < 0));
            if (a.line < 0) continue;
            CHECK((a.line < one.boundary_lines) == (b.line < rev.boundary_lines));
            CHECK(segments_of(one, a.line) == segments_of(rev, b.line));
            // The side is one of its line's segments.
            const auto segs = segments_of(one, a.line);
            CHECK(std::find(segs.begin(), segs.end(), std::array<int, 3>{a.side, a.a, a.b}) !=
                  segs.end());
        }
    }
}

TEST_CASE("a registry taking patches from a previous pass's is the registry built afresh",
          "[shared_edges][heavy]") {
    const test::TeapotPass in;
    const EdgeRegistry& fresh = in.reg;
    const int np = static_cast<int>(in.patches.size());
    for (int every : {1, 2, 5}) {
        std::vector<char> same(np, 0);
        for (int p = 0; p < np; p += every) same[p] = 1;
        const PreviousRegistry previous{&fresh, &in.leaf_start, &same};
        for (int threads : {1, 2}) {
            const EdgeRegistry again =
                build_edge_registry(in.match, in.t.subpatches, threads, previous);
            CHECK(again.offsets == fresh.offsets);
            CHECK(again.interior_keys == fresh.interior_keys);
            CHECK(again.interior_lines == fresh.interior_lines);
            REQUIRE(again.segments.size() == fresh.segments.size());
            for (size_t i = 0; i < fresh.segments.size(); ++i)
                CHECK((again.segments[i].a == fresh.segments[i].a &&
                       again.segments[i].b == fresh.segments[i].b &&
                       again.segments[i].side == fresh.segments[i].side));
            REQUIRE(again.sides.size() == fresh.sides.size());
            for (size_t i = 0; i < fresh.sides.size(); ++i)
                CHECK((again.sides[i].line == fresh.sides[i].line &&
                       again.sides[i].a == fresh.sides[i].a &&
                       again.sides[i].b == fresh.sides[i].b &&
                       again.sides[i].side == fresh.sides[i].side &&
                       again.sides[i].reversed == fresh.sides[i].reversed));
        }
    }
}
