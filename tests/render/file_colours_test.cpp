// SPDX-License-Identifier: MIT
// Scene objects in their files' colours (docs/formats.md, "Scene"): a model
// with face colours (as a STEP/IGES reader gives them) renders in them with
// TRAY, an assembly's placed copies keep their part's colour, a material
// named by the scene wins over the file's, and a file without colours adds
// no material.
#include "model/brep_test_models.h"
#include "render_compare.h"
#include "test_util.h"

#include <seamless/base/error.h>
#include <seamless/model/model.h>
#include <seamless/render/render.h>
#include <seamless/render/scene/camera.h>

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

using namespace seamless;

namespace {

constexpr int kWidth = 64, kHeight = 32, kLevels = 16;

// Two plates with holes side by side in z = 0, each one face on a surface of
// its own: [0, 10]^2 in red and [12, 22] x [0, 10] in blue (face colours, no
// tree, as a coloured part is read).
Model two_colour_plates() {
    Model m = test::plate_with_hole();
    const Model second = test::plate_with_hole();
    append_brep(m.brep, second.brep, 1, test::translation(12, 0, 0));
    BSplineSurface s = second.surfaces[0];
    for (Vec3& p : s.points) p.x += 12;
    s.name = "plate-2";
    m.brep.faces[1].name = "plate-2";
    m.surfaces.push_back(s);
    m.assembly.colours = {{1, 0, 0, 1}, {0, 0, 1, 1}};
    m.assembly.face_colours = {0, 1};
    return m;
}

// A scene looking straight down at the plates, lit by ambient light alone
// (ambient 1: a pixel's intensity is its material's colour); `object` is
// the scene's one object (its "model" is model.json).
Scene plates_scene(const std::filesystem::path& dir, const Model& model,
                   const nlohmann::json& object) {
    test::write_file(dir / "model.json", to_json(model));
    const nlohmann::json s = {{"version", 1},
                              {"camera",
                               {{"eye", {11, 5, 30}},
                                {"look_at", {11, 5, 0}},
                                {"up", {0, 1, 0}},
                                {"fov_deg", 30},
                                {"width", kWidth},
                                {"height", kHeight}}},
                              {"levels", kLevels},
                              {"background", {0.0, 0.0, 0.0}},
                              {"ambient", 1.0},
                              {"materials", {{"green", {{"color", {0.0, 1.0, 0.0}}}}}},
                              {"objects", {object}}};
    test::write_file(dir / "scene.json", s.dump());
    return load_scene(dir / "scene.json");
}

// The pixel that world point p falls in.
std::array<int, 2> pixel_of(const Scene& scene, Vec3 p) {
    const CameraFrame frame(scene.camera);
    const Vec3 c = frame.to_camera(p);
    const double a = c.x / c.z, b = c.y / c.z;
    return {static_cast<int>(std::floor((a / (frame.tan_half * frame.aspect) + 1) * kWidth / 2)),
            static_cast<int>(std::floor((b / frame.tan_half + 1) * kHeight / 2))};
}

std::array<int, 3> levels_at(const Image& im, const Scene& scene, Vec3 p) {
    const auto [x, y] = pixel_of(scene, p);
    return {im.at(x, y, 0), im.at(x, y, 1), im.at(x, y, 2)};
}

Image render_tray(const Scene& scene) {
    RenderOptions o;
    o.method = RenderMethod::tray;
    return render(scene, o);
}

constexpr int kFull = kLevels - 1;

} // namespace

TEST_CASE("A model's face colours are its materials: both colours where their faces are",
          "[scene][file-colours]") {
    const auto dir = test::scratch_dir("file-colours-two");
    const Scene scene = plates_scene(dir, two_colour_plates(), {{"model", "model.json"}});
    REQUIRE(scene.objects.size() == 1);
    CHECK(scene.objects[0].file_colours);
    // The scene's one material and one per file colour.
    REQUIRE(scene.materials.size() == 3);
    REQUIRE(scene.surface_material.size() == 2);
    const Material& left = scene.materials[scene.surface_material[0]];
    const Material& right = scene.materials[scene.surface_material[1]];
    CHECK(left.color == Vec3{1, 0, 0});
    CHECK(right.color == Vec3{0, 0, 1});
    CHECK(left.transmit == 0);

    const Image im = render_tray(scene);
    // The rim of each plate, left and right of its hole, and the holes.
    for (double x : {1.5, 8.5}) CHECK(levels_at(im, scene, {x, 5, 0}) == std::array{kFull, 0, 0});
    for (double x : {13.5, 20.5}) CHECK(levels_at(im, scene, {x, 5, 0}) == std::array{0, 0, kFull});
    for (double x : {5.0, 17.0}) CHECK(levels_at(im, scene, {x, 5, 0}) == std::array{0, 0, 0});
    // Every surface pixel is one of the two colours, and both are there.
    long long red = 0, blue = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            if (!im.surface_at(x, y)) continue;
            const bool is_red =
                im.at(x, y, 0) == kFull && im.at(x, y, 1) == 0 && im.at(x, y, 2) == 0;
            const bool is_blue =
                im.at(x, y, 0) == 0 && im.at(x, y, 1) == 0 && im.at(x, y, 2) == kFull;
            CHECK((is_red || is_blue));
            red += is_red;
            blue += is_blue;
        }
    CHECK(red > 50);
    CHECK(blue > 50);
    test::check_threads_agree(scene, RenderMethod::tray, kWidth, kHeight);
}

TEST_CASE("A material the scene names for an object wins over the file's colours",
          "[scene][file-colours]") {
    const auto dir = test::scratch_dir("file-colours-override");
    const Scene scene =
        plates_scene(dir, two_colour_plates(), {{"model", "model.json"}, {"material", "green"}});
    CHECK_FALSE(scene.objects[0].file_colours);
    CHECK(scene.materials.size() == 1); // no material made for the file's colours
    const Image im = render_tray(scene);
    for (double x : {1.5, 20.5}) CHECK(levels_at(im, scene, {x, 5, 0}) == std::array{0, kFull, 0});
}

TEST_CASE("A model without colours adds no material", "[scene][file-colours]") {
    const auto dir = test::scratch_dir("file-colours-none");
    Model m = two_colour_plates();
    m.assembly = {};
    const Scene scene = plates_scene(dir, m, {{"model", "model.json"}});
    CHECK_FALSE(scene.objects[0].file_colours);
    CHECK(scene.materials.size() == 1);
    CHECK(scene.surface_material == std::vector<int>{0, 0});
}

TEST_CASE("An assembly's placed copies take their part's colour; objects of one file share "
          "its materials",
          "[scene][file-colours]") {
    const auto dir = test::scratch_dir("file-colours-assembly");
    // The plate part red, the tube part's face green and half transparent:
    // four instances, each placed.
    const Model m = test::small_assembly();
    const nlohmann::json object = {{"model", "model.json"}};
    test::write_file(dir / "model.json", to_json(m));
    const nlohmann::json s = {{"version", 1},
                              {"camera", {{"eye", {0, -60, 30}}, {"look_at", {10, 10, 0}}}},
                              {"objects", {object, object}}};
    test::write_file(dir / "scene.json", s.dump());
    const Scene scene = load_scene(dir / "scene.json");
    REQUIRE(scene.objects.size() == 2);
    // Per object: the plate once, the tube three times.
    REQUIRE(scene.surface_material.size() == 8);
    CHECK(scene.materials.size() == 3); // the default grey and the two colours, made once
    for (int o = 0; o < 2; ++o) {
        const int first = scene.objects[o].first_surface;
        CHECK(scene.materials[scene.surface_material[first]].color == Vec3{1, 0, 0});
        for (int k = 1; k < 4; ++k) {
            const Material& tube = scene.materials[scene.surface_material[first + k]];
            CHECK(tube.color == Vec3{0, 1, 0});
            CHECK(tube.transmit == 0.5); // 1 - alpha, seen through
            CHECK(tube.ior == 1);
        }
    }
    // The copies are placed: the tubes' control boxes lie where their instances put them.
    Box3 moved_up;
    for (const Vec3& p : scene.model.surfaces[3].points) moved_up.extend(p);
    CHECK(moved_up.lo.y == Approx(29));
    CHECK(moved_up.lo.z == Approx(5));
}

TEST_CASE("The README's assembly renders in its file's five colours with TRAY; INTRACY refuses "
          "it",
          "[scene][file-colours][heavy]") {
    const Scene scene = load_scene(test::data_dir() / "scenes" / "as1.json");
    REQUIRE(scene.objects.size() == 1);
    CHECK(scene.objects[0].file_colours);
    REQUIRE(scene.materials.size() == 6); // the default grey and the file's five colours
    RenderOptions o;
    o.method = RenderMethod::tray;
    o.width = 120;
    o.height = 90;
    const Image im = render(scene, o);
    // Each colour's pixels: lit, shadowed or highlighted, a pixel's channels
    // keep the colour's proportions (the lights are white) unless a
    // highlight whitens it.
    for (size_t k = 1; k < scene.materials.size(); ++k) {
        const Vec3 c = scene.materials[k].color;
        const double cmax = std::max({c.x, c.y, c.z});
        long long n = 0;
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x) {
                if (!im.surface_at(x, y)) continue;
                const double p[3] = {double(im.at(x, y, 0)), double(im.at(x, y, 1)),
                                     double(im.at(x, y, 2))};
                const double pmax = std::max({p[0], p[1], p[2]});
                n += pmax > 0 && std::abs(p[0] / pmax - c.x / cmax) < 0.05 &&
                     std::abs(p[1] / pmax - c.y / cmax) < 0.05 &&
                     std::abs(p[2] / pmax - c.z / cmax) < 0.05;
            }
        INFO("colour " << c.x << " " << c.y << " " << c.z);
        CHECK(n >= 20);
    }
    o.method = RenderMethod::intracy;
    try {
        render(scene, o);
        FAIL("INTRACY rendered trimmed faces");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()).find("--method tray") != std::string::npos);
    }
}
