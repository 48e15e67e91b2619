// SPDX-License-Identifier: MIT
// The pixels of a certified cluster (certified_pixels.h): on scenes where
// step 7's certificate holds while a light is undecided (scene 3, shadows) or
// step 9's enclosure spans too many levels (the teapot), INTRACY paints such
// sub-screens one ray per pixel; its image stays within one level of the
// image that splits them, and of TRAY and the exact reference as the
// agreement tests require.
#include "render/render_compare.h"
#include "test_util.h"

#include <seamless/render/render.h>

#include <catch2/catch.hpp>

using namespace seamless;

namespace {

Image draw(const Scene& s, RenderMethod m, bool dither, bool fill, RenderStats* st = nullptr) {
    RenderOptions o;
    o.width = 160;
    o.height = 120;
    o.method = m;
    o.dither = dither;
    o.certified_pixels = fill;
    return render(s, o, st);
}

} // namespace

TEST_CASE("Pixels painted from a cluster certificate agree with split sub-screens, TRAY and the "
          "reference",
          "[certified_pixels][heavy]") {
    for (const char* name : {"scene3.json", "teapot.json"}) {
        INFO(name);
        const Scene scene = load_scene(test::data_dir() / "scenes" / name);
        for (const bool dither : {true, false}) {
            INFO("dither " << dither);
            RenderStats st, split_st;
            const Image filled = draw(scene, RenderMethod::intracy, dither, true, &st);
            const Image split = draw(scene, RenderMethod::intracy, dither, false, &split_st);
            const long long light = st.certified_pixels_by_cause[RenderStats::light];
            const long long span = st.certified_pixels_by_cause[RenderStats::span];
            INFO("certified pixels: light " << light << ", span " << span);
            CHECK(light + span > 0);
            CHECK(split_st.certified_pixels_by_cause[RenderStats::light] +
                      split_st.certified_pixels_by_cause[RenderStats::span] ==
                  0);
            // The fill solves its pixels exactly where splitting paints some as
            // clusters (within one level): every pixel within one level.
            const test::ImageComparison c = test::compare(filled, split);
            INFO("max difference " << c.max_difference);
            CHECK(c.max_difference <= 1);
            CHECK(c.surface_mismatch == 0);
            const test::ImageComparison t =
                test::compare(filled, draw(scene, RenderMethod::tray, dither, true));
            INFO("within one level of TRAY: " << t.fraction_within_one());
            CHECK(t.fraction_within_one() >= 0.98);
            CHECK(t.surface_mismatch_off_silhouette == 0);
            if (!dither) {
                const test::ImageComparison r =
                    test::compare(filled, draw(scene, RenderMethod::reference, false, true));
                INFO("max difference to the reference " << r.max_difference);
                CHECK(r.max_difference <= 1);
                CHECK(r.surface_mismatch == 0);
            }
        }
    }
}

TEST_CASE("Pixels painted from a cluster certificate are the same sequentially and in parallel",
          "[certified_pixels][heavy]") {
    const Scene scene = load_scene(test::data_dir() / "scenes" / "scene3.json");
    test::check_threads_agree(scene, RenderMethod::intracy, 160, 120);
}
