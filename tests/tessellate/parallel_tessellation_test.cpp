// SPDX-License-Identifier: MIT
// The tessellation on 1, 2 and 3 threads (TessellationOptions::threads) is one
// and the same output: vertices in the same order at the same bits, the same
// triangles, normals, (u,v), trees, subpatches and statistics, with a
// requested tolerance (several passes), with the paper's planarity test and
// with the naive rule (crack_free off). The work is split differently on each
// count (patches dearest first, subpatches in blocks taken by whichever worker
// is free; vertices numbered in parallel by prefix sums), so these compare
// genuinely different schedules. Without patch trees (TessellationOptions::
// patch_trees false, the CLI's tessellate) the output is the same but for them.
#include "test_util.h"

#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

#include <cstring>
#include <string>

using namespace seamless;

namespace {

// Bitwise equality of two arrays of plain values.
template <class T> bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// trees false: b was made without patch trees (TessellationOptions::
// patch_trees), so its trees are empty and its subpatches' nodes not compared.
void require_same(const Tessellation& a, const Tessellation& b, bool trees = true) {
    CHECK(same_bits(a.mesh.positions, b.mesh.positions));
    CHECK(same_bits(a.mesh.triangles, b.mesh.triangles));
    CHECK(same_bits(a.mesh.triangle_surface, b.mesh.triangle_surface));
    CHECK(same_bits(a.mesh.corner_normals, b.mesh.corner_normals));
    CHECK(same_bits(a.mesh.corner_uvs, b.mesh.corner_uvs));
    if (trees) {
        CHECK(a.trees.roots == b.trees.roots);
        CHECK(a.trees.depth == b.trees.depth);
        REQUIRE(a.trees.nodes.size() == b.trees.nodes.size());
    } else {
        CHECK(b.trees.nodes.empty());
        CHECK(b.trees.roots.empty());
    }
    for (size_t i = 0; trees && i < a.trees.nodes.size(); ++i) {
        const PatchNode &p = a.trees.nodes[i], &q = b.trees.nodes[i];
        INFO("node " << i);
        CHECK((p.child[0] == q.child[0] && p.child[1] == q.child[1] && p.triangle == q.triangle &&
               p.subpatch == q.subpatch && p.split == q.split));
        CHECK(std::memcmp(&p.control_hull, &q.control_hull, sizeof(Box3)) == 0);
        CHECK(std::memcmp(&p.triangle_hull, &q.triangle_hull, sizeof(Box3)) == 0);
    }
    REQUIRE(a.subpatches.size() == b.subpatches.size());
    for (size_t i = 0; i < a.subpatches.size(); ++i) {
        const Subpatch &p = a.subpatches[i], &q = b.subpatches[i];
        INFO("subpatch " << i);
        CHECK((p.patch == q.patch && (!trees || p.node == q.node) && p.rect == q.rect &&
               p.depth == q.depth && p.first_triangle == q.first_triangle &&
               p.triangle_count == q.triangle_count && p.error_bound == q.error_bound &&
               p.fan_error == q.fan_error));
    }
    const TessellationStats &s = a.stats, &t = b.stats;
    CHECK(s.subpatches == t.subpatches);
    CHECK(s.triangles == t.triangles);
    CHECK(s.vertices == t.vertices);
    CHECK(s.shared_edges == t.shared_edges);
    CHECK(s.seams == t.seams);
    CHECK(s.seam_vertices == t.seam_vertices);
    CHECK(s.flipped_surfaces == t.flipped_surfaces);
    CHECK(s.max_depth == t.max_depth);
    CHECK(s.max_error_bound == t.max_error_bound);
    CHECK(s.above_tolerance == t.above_tolerance);
    CHECK(s.passes == t.passes);
}

void check_thread_counts(const std::string& model, double tolerance_of_d_max,
                         bool crack_free = true) {
    const Model m = load_model(test::model_path(model));
    TessellationOptions o;
    o.crack_free = crack_free;
    o.tolerance = tolerance_of_d_max * control_box(m).max_extent();
    o.threads = 1;
    const Tessellation one = tessellate(m, o);
    REQUIRE(one.stats.triangles > 0);
    REQUIRE(one.trees.nodes.size() > one.subpatches.size());
    for (int threads : {2, 3}) {
        INFO(model << ", tolerance " << o.tolerance << ", " << threads << " threads");
        o.threads = threads;
        require_same(one, tessellate(m, o));
        // Without patch trees (the CLI's tessellate): the same mesh, subpatches and stats.
        o.patch_trees = false;
        require_same(one, tessellate(m, o), false);
        o.patch_trees = true;
    }
}

} // namespace

TEST_CASE("Tessellation output is the same on 1, 2 and 3 threads: teapot with a tolerance",
          "[tessellation][parallel][heavy]") {
    check_thread_counts("teapot.json", 1e-3);
}

TEST_CASE("Tessellation output is the same on 1, 2 and 3 threads: CAD fuselage",
          "[tessellation][parallel][heavy]") {
    check_thread_counts("cad/bug28366_fuselage.json", 1e-4);
}

TEST_CASE("Tessellation output is the same on 1, 2 and 3 threads: planarity test",
          "[tessellation][parallel][heavy]") {
    // tolerance_of_d_max 0: the paper's planarity tolerances.
    check_thread_counts("teapot.json", 0);
    check_thread_counts("cad/rounded_cube.json", 0);
}

TEST_CASE("Tessellation output is the same on 1, 2 and 3 threads: naive rule",
          "[tessellation][parallel][heavy]") {
    // Every vertex its exact point: numbered in parallel, also without a tolerance.
    check_thread_counts("teapot.json", 0, false);
    check_thread_counts("cad/bug28366_fuselage.json", 1e-4, false);
}
