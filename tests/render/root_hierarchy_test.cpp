// SPDX-License-Identifier: MIT
// The hierarchy over the patch trees' roots (root_hierarchy.h) and the shadow
// cache of any_hit (trace.h) change only the work, not the answers: on scene 3
// (103 patches), shadow rays between surface points agree with every triangle
// tested one by one, with or without a cached blocker, and nearest_hit finds
// the same triangle as the plain loop over the roots.
#include "test_util.h"

#include <seamless/render/ray_triangle.h>
#include <seamless/render/trace.h>

#include <catch2/catch.hpp>

#include <limits>
#include <random>

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
          "[trace]") {
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
        CHECK(any_hit(ts, P, dir, ts.ray_epsilon, dist, skip) == want);
        CHECK(any_hit(plain, P, dir, ts.ray_epsilon, dist, skip) == want);
        int hint = pick(rng); // any triangle as the cached blocker
        CHECK(any_hit(ts, P, dir, ts.ray_epsilon, dist, skip, nullptr, &hint) == want);
        (want ? blocked : lit)++;

        TraceHit a, b;
        const bool ha = nearest_hit(ts, P, dir, ts.ray_epsilon, kInf, skip, a);
        const bool hb = nearest_hit(plain, P, dir, ts.ray_epsilon, kInf, skip, b);
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
