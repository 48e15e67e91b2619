// SPDX-License-Identifier: MIT
// SHADE steps 3.4 and 4 for clusters: a mirror facing a large wall, and a glass
// plate in front of a wall. The secondary clusters certainly meet one
// triangle each, so INTRACY paints mirror and glass by clusters, and the
// result matches the exact per-pixel reference (which traces the same
// reflected and refracted rays) within one level.
#include "render/render_compare.h"
#include "test_util.h"

#include <seamless/render/render.h>

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

using namespace seamless;

namespace {

// A bilinear quad with corners a, b, c, d (in order) as a model file.
std::string quad(Vec3 a, Vec3 b, Vec3 d, Vec3 c) {
    nlohmann::json pts = {{a.x, a.y, a.z}, {b.x, b.y, b.z}, {d.x, d.y, d.z}, {c.x, c.y, c.z}};
    return nlohmann::json{{"version", 1},
                          {"surfaces",
                           {{{"degree", {1, 1}},
                             {"size", {2, 2}},
                             {"knots_u", {0, 0, 1, 1}},
                             {"knots_v", {0, 0, 1, 1}},
                             {"control_points", pts}}}}}
        .dump();
}

Scene mirror_scene(const std::filesystem::path& dir) {
    // Mirror in the plane x = 0, wall at x = 6, both spanning y, z in [-3, 3].
    test::write_file(dir / "mirror.json",
                     quad({0, -2, -1.5}, {0, 2, -1.5}, {0, -2, 1.5}, {0, 2, 1.5}));
    test::write_file(dir / "wall.json", quad({6, -8, -6}, {6, 8, -6}, {6, -8, 6}, {6, 8, 6}));
    nlohmann::json s = {
        {"version", 1},
        {"camera",
         {{"eye", {3.0, -0.7, 0.4}},
          {"look_at", {0, 0, 0}},
          {"up", {0, 0, 1}},
          {"fov_deg", 60},
          {"width", 64},
          {"height", 48}}},
        {"levels", 16},
        {"background", {0.0, 0.0, 0.2}},
        {"ambient", 0.1},
        {"lights", {{{"position", {4.0, 1.0, 2.0}}, {"color", {1, 1, 1}}}}},
        {"materials",
         {{"mirror",
           {{"color", {0.2, 0.2, 0.2}}, {"diffuse", 0.1}, {"specular", 0.0}, {"reflect", 0.8}}},
          {"wall", {{"color", {0.9, 0.3, 0.2}}, {"diffuse", 0.8}, {"specular", 0.0}}}}},
        {"objects",
         {{{"model", "mirror.json"}, {"material", "mirror"}},
          {{"model", "wall.json"}, {"material", "wall"}}}},
        {"max_depth", 2}};
    test::write_file(dir / "scene.json", s.dump());
    return load_scene(dir / "scene.json");
}

// A glass plate (two parallel quads, normals outward) between camera and wall.
Scene glass_scene(const std::filesystem::path& dir) {
    test::write_file(dir / "front.json",
                     quad({1, -2, -1.5}, {1, -2, 1.5}, {1, 2, -1.5}, {1, 2, 1.5}));
    test::write_file(dir / "back.json",
                     quad({0.8, -2, -1.5}, {0.8, 2, -1.5}, {0.8, -2, 1.5}, {0.8, 2, 1.5}));
    test::write_file(dir / "wall.json", quad({-3, -8, -6}, {-3, -8, 6}, {-3, 8, -6}, {-3, 8, 6}));
    nlohmann::json s = {
        {"version", 1},
        {"camera",
         {{"eye", {4.0, -0.5, 0.3}},
          {"look_at", {0, 0, 0}},
          {"up", {0, 0, 1}},
          {"fov_deg", 50},
          {"width", 64},
          {"height", 48}}},
        {"levels", 16},
        {"background", {0.0, 0.0, 0.2}},
        {"ambient", 0.15},
        {"lights", {{{"position", {2.0, 3.0, 4.0}}, {"color", {1, 1, 1}}}}},
        {"materials",
         {{"glass",
           {{"color", {0.9, 0.9, 0.9}},
            {"diffuse", 0.05},
            {"specular", 0.0},
            {"transmit", 0.85},
            {"ior", 1.5}}},
          {"wall", {{"color", {0.2, 0.8, 0.3}}, {"diffuse", 0.8}, {"specular", 0.0}}}}},
        {"objects",
         {{{"model", "front.json"}, {"material", "glass"}},
          {{"model", "back.json"}, {"material", "glass"}},
          {{"model", "wall.json"}, {"material", "wall"}}}},
        {"max_depth", 3}};
    test::write_file(dir / "scene.json", s.dump());
    return load_scene(dir / "scene.json");
}

} // namespace

TEST_CASE("A glass plate is painted by refracted clusters", "[mirror][heavy]") {
    const Scene scene = glass_scene(test::scratch_dir("glass-cluster"));
    RenderOptions o;
    o.dither = false;
    const Image intracy = render(scene, o);
    o.method = RenderMethod::reference;
    const test::ImageComparison c = test::compare(intracy, render(scene, o));
    INFO("max difference " << c.max_difference);
    CHECK(c.max_difference <= 1);
    CHECK(c.surface_mismatch == 0);
    RenderStats dithered;
    RenderOptions big;
    big.width = 160;
    big.height = 120;
    big.pixel_subscreen = 1; // the cluster path itself, not the small-sub-screen shortcut
    render(scene, big, &dithered);
    CHECK(dithered.secondary_clusters > 0);
}

TEST_CASE("A mirror facing a wall is painted by reflected clusters", "[mirror][heavy]") {
    const Scene scene = mirror_scene(test::scratch_dir("mirror-cluster"));
    RenderOptions o;
    o.dither = false;
    RenderStats st;
    const Image intracy = render(scene, o, &st);
    o.method = RenderMethod::reference;
    const Image reference = render(scene, o);
    const test::ImageComparison c = test::compare(intracy, reference);
    INFO("max difference " << c.max_difference << ", single-pixel fraction "
                           << st.single_pixel_fraction());
    CHECK(c.max_difference <= 1);
    CHECK(c.surface_mismatch == 0);
    // With dithering (two levels per sub-screen) and enough pixels for the
    // wall's shading to change slowly from pixel to pixel, mirror sub-screens
    // are painted from certified reflected clusters.
    RenderStats dithered;
    RenderOptions big;
    big.width = 160;
    big.height = 120;
    big.pixel_subscreen = 1; // the cluster path itself, not the small-sub-screen shortcut
    render(scene, big, &dithered);
    CHECK(dithered.secondary_clusters > 0);
    // The mirror's centre shows the red wall.
    const int cx = intracy.width / 2, cy = intracy.height / 2;
    CHECK(intracy.at(cx, cy, 0) > intracy.at(cx, cy, 2));
    o.method = RenderMethod::tray;
    o.dither = true;
    const test::ImageComparison t = test::compare(render(scene, RenderOptions{}), render(scene, o));
    CHECK(t.fraction_within_one() >= 0.99);
}
