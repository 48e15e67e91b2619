// SPDX-License-Identifier: MIT
// The hierarchy over the patch trees' roots (root_hierarchy.h) and the shadow
// cache of any_hit (trace.h) change only the work, not the answers: on scene 3
// (103 patches), shadow rays between surface points agree with every triangle
// tested one by one, with or without a cached blocker, and nearest_hit finds
// the same triangle as the plain loop over the roots.
#include "test_util.h"

#include <seamless/render/tray/ray_triangle.h>
#include <seamless/render/tray/trace.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>
#include <random>
#include <utility>
#include <vector>

using namespace seamless;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Every triangle not on skip_patch, one by one.
bool any_hit_every_triangle(const TriangleScene& ts, Vec3 o, Vec3 d, double t_min, double t_max,
                            int skip_patch) {
    const TriangleMesh& mesh = ts.tess.mesh;
    const TriangleRay ray(o, d);
    RayTriangleHit h;
    for (int f = 0; f < mesh.triangle_count(); ++f) {
        if (ts.triangle_patch[f] == skip_patch) continue;
        const auto& tri = mesh.triangles[f];
        if (intersect_triangle(ray, mesh.positions[tri[0]], mesh.positions[tri[1]],
                               mesh.positions[tri[2]], t_max, h) &&
            h.t > t_min)
            return true;
    }
    return false;
}

} // namespace

TEST_CASE("Shadow and nearest rays through the root hierarchy agree with the plain traversal",
          "[trace][heavy]") {
    const Scene scene = load_scene(test::data_dir() / "scenes" / "scene3.json");
    const TriangleScene ts = build_triangle_scene(scene);
    TriangleScene plain = ts; // no hierarchy: the roots one after another
    plain.root_hierarchy = RootHierarchy{};
    REQUIRE(ts.root_hierarchy.nodes.size() == 2 * ts.tess.trees.roots.size() - 1);

    const TriangleMesh& mesh = ts.tess.mesh;
    const int F = mesh.triangle_count();
    std::mt19937 rng(10);
    std::uniform_int_distribution<int> pick(0, F - 1);
    int blocked = 0, lit = 0;
    for (int i = 0; i < 3000; ++i) {
        const int f = pick(rng), g = pick(rng);
        const auto centre = [&](int k) {
            const auto& tri = mesh.triangles[k];
            return (1.0 / 3) *
                   (mesh.positions[tri[0]] + mesh.positions[tri[1]] + mesh.positions[tri[2]]);
        };
        // From a surface point towards a light or to 99 % of the way to
        // another surface point (a segment that ends on a surface is decided
        // by rounding: the slab and triangle tests may disagree at t_max).
        const Vec3 P = centre(f);
        const bool to_light = i % 3 == 0;
        const Vec3 Q = to_light ? scene.lights[i / 3 % scene.lights.size()].position : centre(g);
        const double full = norm(Q - P);
        if (!(full > 0)) continue;
        const Vec3 dir = (Q - P) / full;
        const double dist = to_light ? full : 0.99 * full;
        const int skip = ts.triangle_patch[f];
        const bool want = any_hit_every_triangle(ts, P, dir, ts.ray_epsilon, dist, skip);
        CHECK(any_hit(ts, {P, dir, ts.ray_epsilon, dist, skip}) == want);
        CHECK(any_hit(plain, {P, dir, ts.ray_epsilon, dist, skip}) == want);
        int hint = pick(rng); // any triangle as the cached blocker
        CHECK(any_hit(ts, {P, dir, ts.ray_epsilon, dist, skip}, nullptr, &hint) == want);
        (want ? blocked : lit)++;

        TraceHit a, b;
        const bool ha = nearest_hit(ts, {P, dir, ts.ray_epsilon, kInf, skip}, a);
        const bool hb = nearest_hit(plain, {P, dir, ts.ray_epsilon, kInf, skip}, b);
        REQUIRE(ha == hb);
        if (ha) {
            CHECK(a.triangle == b.triangle);
            CHECK(a.t == b.t);
        }
    }
    // Both answers occur often enough for the comparison to mean something.
    CHECK(blocked > 300);
    CHECK(lit > 300);
}

TEST_CASE("The root hierarchy holds every root with triangles once, inside its parents",
          "[trace][heavy]") {
    for (const char* name : {"scene2.json", "scene3.json", "teapot.json"}) {
        const Scene scene = load_scene(test::data_dir() / "scenes" / name);
        const TriangleScene ts = build_triangle_scene(scene);
        const PatchTrees& trees = ts.tess.trees;
        const RootHierarchy& h = ts.root_hierarchy;
        std::vector<int> seen(trees.roots.size(), 0);
        int with_triangles = 0;
        for (size_t r = 0; r < trees.roots.size(); ++r)
            with_triangles += !trees.nodes[trees.roots[r]].triangle_hull.empty();
        const auto inside = [](const Box3& a, const Box3& b) {
            return b.lo.x <= a.lo.x && b.lo.y <= a.lo.y && b.lo.z <= a.lo.z && a.hi.x <= b.hi.x &&
                   a.hi.y <= b.hi.y && a.hi.z <= b.hi.z;
        };
        // Depth first from the top, checking each child's box against its parent's.
        std::vector<std::pair<int, int>> stack{{0, 0}};
        int deepest = 0;
        while (!stack.empty()) {
            const auto [i, level] = stack.back();
            stack.pop_back();
            deepest = std::max(deepest, level);
            const RootNode& n = h.nodes[static_cast<size_t>(i)];
            if (n.patch >= 0) {
                ++seen[static_cast<size_t>(n.patch)];
                CHECK(inside(trees.nodes[trees.roots[n.patch]].triangle_hull, n.box));
                continue;
            }
            for (int c : n.child) {
                REQUIRE(c > 0);
                CHECK(inside(h.nodes[static_cast<size_t>(c)].box, n.box));
                stack.push_back({c, level + 1});
            }
        }
        CHECK(deepest == h.depth);
        CHECK(h.depth < 64);
        int leaves = 0;
        for (size_t r = 0; r < trees.roots.size(); ++r) {
            CHECK(seen[r] == (trees.nodes[trees.roots[r]].triangle_hull.empty() ? 0 : 1));
            leaves += seen[r];
        }
        CHECK(leaves == with_triangles);
    }
}

TEST_CASE("shade_ray's shadow cache per recursion depth changes no intensity (scene 2)",
          "[trace]") {
    const Scene scene = load_scene(test::data_dir() / "scenes" / "scene2.json");
    const TriangleScene ts = build_triangle_scene(scene);
    const TriangleMesh& mesh = ts.tess.mesh;
    std::mt19937 rng(12);
    std::uniform_int_distribution<int> pick(0, mesh.triangle_count() - 1);
    int secondary = 0;
    for (int i = 0; i < 2000; ++i) {
        const int f = pick(rng);
        const auto& tri = mesh.triangles[f];
        const Vec3 P =
            (1.0 / 3) * (mesh.positions[tri[0]] + mesh.positions[tri[1]] + mesh.positions[tri[2]]);
        const auto& cn = mesh.corner_normals[f];
        const Vec3 N = normalize(cn[0] + cn[1] + cn[2]);
        const Vec3 view = normalize(scene.camera.eye - P);
        const int material = ts.triangle_material[f], patch = ts.triangle_patch[f];
        const Material& m = scene.materials[material];
        secondary += m.reflect > 0 || m.transmit > 0;
        long long tests = 0; // counted: no cache
        const auto plain = shade_ray(scene, ts, {P, N, material, patch, view}, 0, &tests);
        const auto cached = shade_ray(scene, ts, {P, N, material, patch, view}, 0);
        for (int c = 0; c < 3; ++c) CHECK(plain[c] == cached[c]);
    }
    CHECK(secondary > 50);
}
