// SPDX-License-Identifier: MIT
// Binary patch trees (Proposition 11, remark 2): hulls hold their triangles,
// sons and subpatch; traversal finds exactly the triangles a box query needs.
#include "test_util.h"

#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

#include <set>

using namespace seamless;

namespace {

bool contains(const Box3& outer, const Box3& inner, double tol) {
    if (inner.empty()) return true;
    return inner.lo.x >= outer.lo.x - tol && inner.lo.y >= outer.lo.y - tol &&
           inner.lo.z >= outer.lo.z - tol && inner.hi.x <= outer.hi.x + tol &&
           inner.hi.y <= outer.hi.y + tol && inner.hi.z <= outer.hi.z + tol;
}

Box3 triangle_box(const TriangleMesh& m, int f) {
    Box3 b;
    for (int v : m.triangles[f]) b.extend(m.positions[v]);
    return b;
}

} // namespace

TEST_CASE("patch tree hulls contain their triangles, sons and subpatches", "[patch_tree][heavy]") {
    const Model m = load_model(test::model_path("teapot.json"));
    const auto patches = bezier_patches(m);
    const Tessellation t = tessellate(m, patches, {});
    const PatchTrees& tr = t.trees;
    const double tol = 1e-12 * t.stats.d_max;
    REQUIRE(tr.roots.size() == patches.size());
    std::vector<int> seen(t.mesh.triangle_count(), 0);
    std::vector<int> fathers(tr.nodes.size(), 0);
    for (size_t i = 0; i < tr.nodes.size(); ++i) {
        const PatchNode& n = tr.nodes[i];
        if (n.triangle >= 0) {
            ++seen[n.triangle];
            CHECK(contains(n.triangle_hull, triangle_box(t.mesh, n.triangle), 0));
        }
        for (int c : n.child) {
            if (c < 0) continue;
            REQUIRE(c > static_cast<int>(i));
            ++fathers[c];
            CHECK(contains(n.triangle_hull, tr.nodes[c].triangle_hull, 0));
            CHECK(contains(n.control_hull, tr.nodes[c].control_hull, tol));
        }
        // Binary: split nodes have two sons.
        if (n.split >= 0) CHECK((n.child[0] >= 0 && n.child[1] >= 0));
    }
    for (int s : seen) CHECK(s == 1); // every triangle is exactly one leaf
    for (int r : tr.roots) CHECK(fathers[r] == 0);
    // The surface of each subpatch lies in its node's control hull.
    for (const Subpatch& sp : t.subpatches) {
        const Box3& hull = tr.nodes[sp.node].control_hull;
        for (double a : {0.0, 0.3, 0.5, 1.0})
            for (double b : {0.0, 0.7, 1.0}) {
                const double s =
                    param_of(sp.rect.s0) + a * (param_of(sp.rect.s1) - param_of(sp.rect.s0));
                const double u =
                    param_of(sp.rect.t0) + b * (param_of(sp.rect.t1) - param_of(sp.rect.t0));
                CHECK(contains(hull,
                               Box3{evaluate(patches[sp.patch], s, u).point,
                                    evaluate(patches[sp.patch], s, u).point},
                               tol));
            }
    }
}

TEST_CASE("traversal visits exactly the triangles whose hulls meet the query",
          "[patch_tree][heavy]") {
    const Model m = load_model(test::model_path("teacup.json"));
    const Tessellation t = tessellate(m, {});
    for (const Box3& q : {Box3{{-0.2, 0.3, -1}, {0.1, 0.5, 1}}, Box3{{0.9, 0, -0.1}, {1, 0.1, 0.1}},
                          Box3{{5, 5, 5}, {6, 6, 6}}}) {
        std::set<int> expected, got;
        for (int f = 0; f < t.mesh.triangle_count(); ++f)
            if (triangle_box(t.mesh, f).overlaps(q)) expected.insert(f);
        int visited = 0;
        visit_candidate_triangles(
            t.trees, [&](const Box3& b) { return b.overlaps(q); },
            [&](int f) {
                ++visited;
                got.insert(f);
            });
        CHECK(got == expected);
        CHECK(visited == static_cast<int>(got.size()));
    }
}
