// SPDX-License-Identifier: MIT
// The flat layout of the patch trees (flat_patch_trees.h) compares the same
// hulls and meets the same triangles in the same order as the stack visit
// over PatchTrees (visit_candidate_triangles), on scene 3's 103 patch trees,
// for box predicates that cut the trees at many places, and stops where the
// visitor says so.
#include "test_util.h"

#include <seamless/render/tray/flat_patch_trees.h>
#include <seamless/render/tray/trace.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

using namespace seamless;

TEST_CASE("The flat patch trees visit the hulls and triangles of the stack visit in its order",
          "[flat_patch_trees]") {
    const Scene scene = load_scene(test::data_dir() / "scenes" / "scene3.json");
    const TriangleScene ts = build_triangle_scene(scene);
    const FlatPatchTrees& f = ts.flat_trees;
    REQUIRE(f.first.size() == ts.tess.trees.roots.size() + 1);
    REQUIRE(f.nodes.size() <= ts.tess.trees.nodes.size());
    for (const FlatNode& n : f.nodes) CHECK_FALSE(n.hull.empty());
    Box3 all;
    for (const Vec3& v : ts.tess.mesh.positions) all.extend(v);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    int cut = 0;
    for (int k = 0; k < 200; ++k) {
        // A random query box; k == 0: everything.
        Box3 q;
        for (int i = 0; i < 3; ++i) {
            const double a = all.lo[i] + u(rng) * (all.hi[i] - all.lo[i]),
                         b = all.lo[i] + u(rng) * (all.hi[i] - all.lo[i]);
            q.lo[i] = k == 0 ? all.lo[i] : std::min(a, b);
            q.hi[i] = k == 0 ? all.hi[i] : std::max(a, b);
        }
        std::vector<int> stack_hulls, flat_hulls, stack_tris, flat_tris;
        auto pred = [&](std::vector<int>& log) {
            return [&q, &log](const Box3& b) {
                log.push_back(static_cast<int>(1e6 * (b.lo.x + b.hi.y)));
                return b.overlaps(q);
            };
        };
        visit_candidate_triangles(ts.tess.trees, pred(stack_hulls),
                                  [&](int t) { stack_tris.push_back(t); });
        visit_flat_candidates(f, pred(flat_hulls), [&](int t) { flat_tris.push_back(t); });
        CHECK(stack_hulls == flat_hulls);
        CHECK(stack_tris == flat_tris);
        cut += stack_tris.size() < static_cast<size_t>(ts.tess.mesh.triangle_count());
        // Stopping at the visitor's word: the triangles up to the third of a patch.
        for (int p = 0; p < static_cast<int>(f.first.size()) - 1; p += 17) {
            std::vector<int> seen;
            const bool stopped = visit_flat_tree(f, p, pred(flat_hulls), [&](int t) {
                seen.push_back(t);
                return seen.size() == 3;
            });
            CHECK(stopped == (seen.size() == 3));
            CHECK(seen.size() <= 3);
        }
    }
    CHECK(cut > 150); // the predicates cut the trees
}
