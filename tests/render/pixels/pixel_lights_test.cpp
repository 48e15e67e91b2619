// SPDX-License-Identifier: MIT
// The light certificate of a small sub-screen's hits (pixel_lights.h): a light
// certified to reach a box of points reaches every point of it (no shadow ray
// from a point of the box meets a triangle of another patch), on scene 3's
// lamp, table and walls; and it is not vacuous (some boxes are certified, and
// a box whose own shadow rays are blocked is not).
#include <seamless/render/pixels/pixel_lights.h>
#include <seamless/render/scene/camera.h>
#include <seamless/render/scene/scene.h>
#include <seamless/render/tray/trace.h>

#include <catch2/catch.hpp>

#include "test_util.h"

#include <limits>
#include <random>

using namespace seamless;

TEST_CASE("A light certified for a box of hit points reaches every point of the box",
          "[pixel_lights][heavy]") {
    const Scene scene = load_scene(test::data_dir() / "scenes" / "scene3.json");
    const TriangleScene ts = build_triangle_scene(scene);
    // The light planes kept for the render (add_light_planes, formed on first
    // use) decide as the planes formed per test.
    TriangleScene tp = ts;
    add_light_planes(scene, tp);
    REQUIRE(tp.light_planes.size() == scene.lights.size() * ts.tess.mesh.triangles.size());
    CHECK(tp.light_planes.formed() == 0);
    Camera cam = scene.camera;
    cam.width = 160;
    cam.height = 120;
    const CameraFrame f(cam);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    const size_t nl = scene.lights.size();
    std::vector<char> lit(nl);
    std::vector<int> hints(nl, -1), hints_planes(nl, -1);
    std::vector<char> lit_planes(nl);
    int certified = 0, refused = 0, refused_blocked = 0;
    for (int y = 0; y < cam.height; y += 3)
        for (int x = 0; x < cam.width; x += 3) {
            // A 3 x 3 block of primary rays; the box of their hits on one patch.
            IVec<3> Pw = IVec<3>::empty();
            int patch = -1;
            bool one = true;
            for (int j = 0; j < 3 && one; ++j)
                for (int i = 0; i < 3 && one; ++i) {
                    const Vec3 d = f.to_world_direction(
                        {f.screen_a(x + i + 0.5), f.screen_b(y + j + 0.5), 1.0});
                    TraceHit h;
                    if (!nearest_hit(
                            ts,
                            {f.eye, normalize(d), 0, std::numeric_limits<double>::infinity(), -1},
                            h) ||
                        (patch >= 0 && h.patch != patch)) {
                        one = false;
                        break;
                    }
                    patch = h.patch;
                    for (int c = 0; c < 3; ++c) Pw[c] = hull(Pw[c], Interval(h.point[c]));
                }
            if (!one || patch < 0) continue;
            lights_reaching_box(scene, ts, Pw, patch, lit.data(), hints.data());
            lights_reaching_box(scene, tp, Pw, patch, lit_planes.data(), hints_planes.data());
            CHECK(lit == lit_planes);
            for (size_t l = 0; l < nl; ++l) {
                // Shadow rays from the box's corners and from random points of it.
                bool any_blocked = false;
                for (int k = 0; k < 16; ++k) {
                    Vec3 P;
                    for (int c = 0; c < 3; ++c)
                        P[c] = k < 8 ? ((k >> c) & 1 ? Pw[c].hi() : Pw[c].lo())
                                     : Pw[c].lo() + u(rng) * (Pw[c].hi() - Pw[c].lo());
                    const Vec3 L = scene.lights[l].position - P;
                    const double dist = norm(L);
                    const bool blocked =
                        any_hit(ts, {P, L / dist, ts.ray_epsilon, dist, patch}, nullptr, nullptr);
                    any_blocked |= blocked;
                    if (lit[l]) CHECK_FALSE(blocked);
                }
                if (lit[l])
                    ++certified;
                else {
                    ++refused;
                    refused_blocked += any_blocked;
                }
            }
        }
    INFO("certified " << certified << ", refused " << refused << " (" << refused_blocked
                      << " with a blocked shadow ray)");
    CHECK(certified > 100);
    CHECK(refused_blocked > 10);
    // Only the planes the tests asked for were formed.
    CHECK(tp.light_planes.formed() > 0);
    CHECK(tp.light_planes.formed() < tp.light_planes.size());
}
