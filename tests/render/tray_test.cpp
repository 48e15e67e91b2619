// SPDX-License-Identifier: MIT
// TRAY (paper section 8) against INTRACY: the same pictures up to the planar
// approximation of the tessellation (99% of pixels within one level, the same
// surface pixels off the silhouettes), on the default scene and on single
// patches (face-on, grazing, a pole in view); the same image sequentially and in
// parallel. Also the ray-box and watertight ray-triangle tests it is built on.
#include "render_compare.h"
#include "scene_fixtures.h"
#include "test_util.h"

#include <seamless/model/model.h>
#include <seamless/render/render.h>
#include <seamless/render/tray/ray_triangle.h>

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>

using namespace seamless;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void check_tray_against_intracy(const Scene& scene, int w, int h) {
    RenderOptions o;
    o.width = w;
    o.height = h;
    o.levels = 16;
    RenderStats si, st;
    o.method = RenderMethod::intracy;
    const Image intracy = render(scene, o, &si);
    o.method = RenderMethod::tray;
    const Image tray = render(scene, o, &st);
    const test::ImageComparison c = test::compare(tray, intracy);
    INFO("within one level " << c.fraction_within_one() << ", max difference " << c.max_difference
                             << ", surface mismatches " << c.surface_mismatch << " ("
                             << c.surface_mismatch_off_silhouette
                             << " off the silhouette), triangles " << st.triangles);
    CHECK(c.fraction_within_one() >= 0.99);
    CHECK(c.surface_mismatch_off_silhouette == 0);
    // TRAY's statistics: every pixel a one-pixel sub-screen with one primary ray.
    const long long pixels = static_cast<long long>(w) * h;
    CHECK(st.primary_rays == pixels);
    CHECK(st.single_pixels == pixels);
    CHECK(st.subscreens_by_size == std::map<long long, long long>{{1, pixels}});
    CHECK(st.triangles > 0);
    CHECK(st.background_pixels == pixels - std::count(tray.surface.begin(), tray.surface.end(), 1));
}

} // namespace

TEST_CASE("Ray-box slab test", "[tray]") {
    Box3 box;
    box.extend(Vec3{0, 0, 0});
    box.extend(Vec3{1, 1, 1});
    // Axis-parallel rays, also with the origin on a slab plane (0 * inf).
    CHECK(ray_hits_box(TriangleRay({0.5, 0.5, -1}, {0, 0, 1}), box, kInf));
    CHECK(ray_hits_box(TriangleRay({0, 0.5, -1}, {0, 0, 1}), box, kInf));
    CHECK(ray_hits_box(TriangleRay({1, 1, -1}, {0, 0, 1}), box, kInf));
    CHECK_FALSE(ray_hits_box(TriangleRay({1.5, 0.5, -1}, {0, 0, 1}), box, kInf));
    CHECK_FALSE(ray_hits_box(TriangleRay({0.5, 0.5, -1}, {0, 0, -1}), box, kInf));
    // Beyond t_max (the nearest hit so far) the box is pruned.
    CHECK_FALSE(ray_hits_box(TriangleRay({0.5, 0.5, -1}, {0, 0, 1}), box, 0.5));
    CHECK(ray_hits_box(TriangleRay({0.5, 0.5, -1}, {0, 0, 1}), box, 1.0));
    // A flat box (a triangle in z = 0) hit at a slant.
    Box3 flat;
    flat.extend(Vec3{0, 0, 0});
    flat.extend(Vec3{1, 1, 0});
    CHECK(ray_hits_box(TriangleRay({-0.3, 0.1, 1}, {1.3, 0.9, -1}), flat, kInf));
}

TEST_CASE("The slab test of rays with finite slabs decides as the per-axis loop", "[tray]") {
    // The loop with a swap per axis and an exit after each (the slab test for
    // every ray), against ray_hits_box's branch for rays whose 1 / d are finite.
    const auto loop = [](const TriangleRay& ray, const Box3& box, double t_max) {
        constexpr double eps = std::numeric_limits<double>::epsilon() * 0.5;
        constexpr double widen = 1 + 2 * (3 * eps) / (1 - 3 * eps);
        double t0 = 0, t1 = t_max;
        for (int i = 0; i < 3; ++i) {
            double tn = (box.lo[i] - ray.origin[i]) * ray.inv_dir[i],
                   tf = (box.hi[i] - ray.origin[i]) * ray.inv_dir[i];
            if (tn > tf) std::swap(tn, tf);
            tf *= widen;
            t0 = std::max(t0, tn);
            t1 = std::min(t1, tf);
            if (t0 > t1) return false;
        }
        return true;
    };
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    int hits = 0, misses = 0;
    for (int k = 0; k < 20000; ++k) {
        // Grid coordinates, so that origins often lie on slab planes.
        const auto g = [&] { return std::round(8 * u(rng)) / 4; };
        const Vec3 o{g(), g(), g()}, d{u(rng), u(rng), k % 7 == 0 ? 1e-300 : u(rng)};
        const TriangleRay ray(o, d);
        REQUIRE(ray.finite_slabs);
        Box3 box;
        box.extend(Vec3{g(), g(), g()});
        box.extend(Vec3{g(), g(), g()});
        const double t_max = k % 3 == 0 ? kInf : 2 * std::abs(u(rng));
        const bool expected = loop(ray, box, t_max);
        CHECK(ray_hits_box(ray, box, t_max) == expected);
        hits += expected;
        misses += !expected;
    }
    CHECK(hits > 1000);
    CHECK(misses > 1000);
    CHECK_FALSE(TriangleRay({0, 0, 0}, {1, 0, 1e-320}).finite_slabs); // 1 / d overflows
    CHECK_FALSE(TriangleRay({0, 0, 0}, {1, 0, 1}).finite_slabs);
}

TEST_CASE("Watertight ray-triangle test", "[tray]") {
    const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{1, 1, 0};
    RayTriangleHit h;
    REQUIRE(intersect_triangle(TriangleRay({0.2, 0.3, 2}, {0, 0, -1}), a, b, c, kInf, h));
    CHECK(h.t == Approx(2));
    CHECK(h.b0 == Approx(0.5));
    CHECK(h.b1 == Approx(0.2));
    CHECK(h.b2 == Approx(0.3));
    // Both windings; behind the origin and beyond t_max there is no hit.
    CHECK(intersect_triangle(TriangleRay({0.2, 0.3, 2}, {0, 0, -1}), a, c, b, kInf, h));
    CHECK_FALSE(intersect_triangle(TriangleRay({0.2, 0.3, 2}, {0, 0, 1}), a, b, c, kInf, h));
    CHECK_FALSE(intersect_triangle(TriangleRay({0.2, 0.3, 2}, {0, 0, -1}), a, b, c, 1.5, h));
    CHECK_FALSE(intersect_triangle(TriangleRay({0.8, 0.8, 2}, {0, 0, -1}), a, b, c, kInf, h));
    // Rays through the shared edge b-c of the quad (a, b, c) + (b, d, c), at
    // awkward slants: each hits at least one of the two triangles.
    int missed = 0;
    for (int k = 1; k < 1000; ++k) {
        const double s = k / 1000.0;
        const Vec3 on_edge = lerp(b, c, s);
        const Vec3 o{0.37 + 0.001 * k, -0.61, 1.7};
        const TriangleRay ray(o, on_edge - o);
        const bool hit1 = intersect_triangle(ray, a, b, c, kInf, h);
        const bool hit2 = intersect_triangle(ray, b, d, c, kInf, h);
        missed += !hit1 && !hit2;
    }
    CHECK(missed == 0);
}

TEST_CASE("TRAY agrees with INTRACY on the default scene", "[tray][heavy]") {
    check_tray_against_intracy(load_scene(test::data_dir() / "scenes" / "teapot.json"), 96, 72);
}

TEST_CASE("TRAY agrees with INTRACY on single patches: face-on, grazing", "[tray]") {
    auto dir = test::scratch_dir("tray-patch");
    SECTION("face-on") {
        check_tray_against_intracy(
            test::one_model_scene(dir, test::dome(), {0.1, 0.2, 4}, {0, 0, 0}, {0, 1, 0}), 64, 48);
    }
    SECTION("grazing") {
        check_tray_against_intracy(
            test::one_model_scene(dir, test::dome(), {5, 0.5, 0.35}, {0, 0, 0}), 64, 48);
    }
}

TEST_CASE("TRAY agrees with INTRACY with a pole of the teapot in view", "[tray][heavy]") {
    auto dir = test::scratch_dir("tray-pole");
    const Model teapot = load_model(test::model_path("teapot.json"));
    Model lid;
    for (int k = 20; k < 28; ++k) lid.surfaces.push_back(teapot.surfaces[k]); // knob and lid
    check_tray_against_intracy(test::one_model_scene(dir, to_json(lid), {0.3, -0.4, 5}, {0, 0, 3}),
                               64, 48);
}

TEST_CASE("TRAY gives the same image sequentially and in parallel", "[tray][heavy]") {
    const Scene scene = load_scene(test::data_dir() / "scenes" / "teapot.json");
    test::check_threads_agree(scene, RenderMethod::tray, 80, 60);
}
