// SPDX-License-Identifier: MIT
// INTRACY against the per-pixel exact reference (Hansen-Sengupta on the patches
// for every pixel): certified background, one level everywhere without dither,
// 99% within one level with dither; on the default scene and on single-patch
// scenes chosen to be stiff (face-on, edge-on, grazing, a pole in view).
#include "render_compare.h"
#include "scene_fixtures.h"
#include "test_util.h"

#include <seamless/model/model.h>
#include <seamless/render/render.h>

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

using namespace seamless;

namespace {

struct Renders {
    Image intracy, intracy_no_dither, reference;
    RenderStats stats;
};

Renders render_all(const Scene& scene, int w, int h) {
    Renders r;
    RenderOptions o;
    o.width = w;
    o.height = h;
    o.method = RenderMethod::reference;
    r.reference = render(scene, o);
    o.method = RenderMethod::intracy;
    r.intracy = render(scene, o, &r.stats);
    o.dither = false;
    r.intracy_no_dither = render(scene, o);
    return r;
}

void check_against_reference(const Renders& r) {
    const test::ImageComparison nd = test::compare(r.intracy_no_dither, r.reference);
    INFO("no dither: max difference " << nd.max_difference << ", surface mismatches "
                                      << nd.surface_mismatch);
    CHECK(nd.max_difference <= 1);
    CHECK(nd.surface_mismatch == 0); // background is certified, hits are exact
    const test::ImageComparison d = test::compare(r.intracy, r.reference);
    INFO("dither: within one level " << d.fraction_within_one() << ", surface mismatches "
                                     << d.surface_mismatch);
    CHECK(d.fraction_within_one() >= 0.99);
    CHECK(d.surface_mismatch == 0);
}

} // namespace

TEST_CASE("INTRACY agrees with the per-pixel reference on the default scene", "[intracy][heavy]") {
    const Scene scene = load_scene(test::data_dir() / "scenes" / "teapot.json");
    const Renders r = render_all(scene, 96, 72);
    check_against_reference(r);
    // Some of the screen is painted from clusters, not pixel by pixel.
    CHECK(r.stats.single_pixel_fraction() < 0.6);
}

TEST_CASE("INTRACY on single patches: face-on, edge-on, grazing", "[intracy][heavy]") {
    auto dir = test::scratch_dir("intracy-patch");
    SECTION("face-on") {
        check_against_reference(render_all(
            test::one_model_scene(dir, test::dome(), {0.1, 0.2, 4}, {0, 0, 0}, {0, 1, 0}), 64, 48));
    }
    SECTION("edge-on") {
        check_against_reference(render_all(
            test::one_model_scene(dir, test::dome(), {5, 0.3, 0.0}, {0, 0, 0.0}), 64, 48));
    }
    SECTION("grazing") {
        check_against_reference(render_all(
            test::one_model_scene(dir, test::dome(), {5, 0.5, 0.35}, {0, 0, 0}), 64, 48));
    }
}

TEST_CASE("INTRACY with a pole of the teapot in view", "[intracy][heavy]") {
    auto dir = test::scratch_dir("intracy-pole");
    const Model teapot = load_model(test::model_path("teapot.json"));
    Model lid;
    for (int k = 20; k < 28; ++k)
        lid.surfaces.push_back(teapot.surfaces[k]); // knob and lid: poles at the top
    check_against_reference(
        render_all(test::one_model_scene(dir, to_json(lid), {0.3, -0.4, 5}, {0, 0, 3}), 64, 48));
}

TEST_CASE("INTRACY gives the same image sequentially and in parallel", "[intracy][heavy]") {
    const Scene scene = load_scene(test::data_dir() / "scenes" / "teapot.json");
    test::check_threads_agree(scene, RenderMethod::intracy, 80, 60);
}

namespace {

// A flat bicubic plate over [x0, x1] x [y0, y1] at height z.
nlohmann::json plate(const std::string& name, double x0, double x1, double y0, double y1,
                     double z) {
    nlohmann::json pts = nlohmann::json::array();
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            pts.push_back({x0 + (x1 - x0) * i / 3, y0 + (y1 - y0) * j / 3, z});
    return {{"name", name},
            {"degree", {3, 3}},
            {"size", {4, 4}},
            {"knots_u", {0, 0, 0, 0, 1, 1, 1, 1}},
            {"knots_v", {0, 0, 0, 0, 1, 1, 1, 1}},
            {"control_points", pts}};
}

} // namespace

TEST_CASE("INTRACY with a thin plate lying just above another and casting its shadow",
          "[intracy][heavy]") {
    // Depths of the floor and the mat overlap over a sub-screen (step 7 needs
    // the separating plane), and the floating roof's shadow on the floor is
    // blocked by a surface of its triangles, not by one.
    auto dir = test::scratch_dir("intracy-plates");
    const nlohmann::json model = {
        {"version", 1},
        {"surfaces",
         {plate("floor", -1, 1, -1, 1, 0), plate("mat", -0.45, 0.35, -0.4, 0.3, 0.01),
          plate("roof", 0.2, 0.9, -0.95, -0.35, 0.5)}}};
    const Renders r =
        render_all(test::one_model_scene(dir, model.dump(), {0.5, -2.5, 2.0}, {0, 0, 0}), 96, 72);
    check_against_reference(r);
    CHECK(r.stats.nearest_by_plane > 0);
    CHECK(r.stats.lights_blocked_by_surface > 0);
}
