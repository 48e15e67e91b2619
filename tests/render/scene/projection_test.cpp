// SPDX-License-Identifier: MIT
// INTRACY step 1 (projection.h): project_scene builds every patch in place and
// in parallel; the result must not depend on the thread count, and each
// patch's forms must be those of its camera-space control points
// (patch_forms by value, the reference) and, where SHADE needs them, of its
// world-space ones.
#include "test_util.h"

#include <seamless/render/scene/projection.h>
#include <seamless/render/scene/scene.h>
#include <seamless/render/tray/trace.h>
#include <seamless/spline/knot_insertion.h>

#include <catch2/catch.hpp>

#include <vector>

using namespace seamless;

namespace {

bool same(Interval x, Interval y) {
    return x.lo() == y.lo() && x.hi() == y.hi();
}

// Every coefficient of f's degrees and its hull data equal bit for bit.
void check_same_forms(const PatchForms& f, const PatchForms& g) {
    const PowerForm* a[] = {&f.X, &f.Xs, &f.Xt, &f.Xss, &f.Xst, &f.Xtt};
    const PowerForm* b[] = {&g.X, &g.Xs, &g.Xt, &g.Xss, &g.Xst, &g.Xtt};
    for (int k = 0; k < 6; ++k) {
        REQUIRE(a[k]->p == b[k]->p);
        REQUIRE(a[k]->q == b[k]->q);
        REQUIRE(a[k]->dim == b[k]->dim);
        int differ = 0;
        for (int c = 0; c < a[k]->dim; ++c)
            for (int i = 0; i <= a[k]->p; ++i)
                for (int j = 0; j <= a[k]->q; ++j)
                    differ += !same(a[k]->at(c, i, j), b[k]->at(c, i, j));
        CHECK(differ == 0);
    }
    CHECK(f.rational == g.rational);
    CHECK(same(f.w_hull, g.w_hull));
    for (int c = 0; c < 3; ++c) CHECK(same(f.control_hull[c], g.control_hull[c]));
}

} // namespace

TEST_CASE("project_scene: the same patches on 1 and 2 threads, forms as patch_forms gives them",
          "[projection]") {
    for (const char* name : {"teapot.json", "scene1.json"}) {
        INFO(name);
        const Scene scene = load_scene(test::data_dir() / "scenes" / name);
        const ProjectedScene one = project_scene(scene, 64, 48, 1);
        const ProjectedScene two = project_scene(scene, 64, 48, 2);
        std::vector<BezierPatch> world;
        for (size_t k = 0; k < scene.model.surfaces.size(); ++k)
            for (const BezierPatch& b :
                 bezier_patches(scene.model.surfaces[k], static_cast<int>(k)))
                world.push_back(b);
        REQUIRE(one.patches.size() == world.size());
        REQUIRE(two.patches.size() == world.size());
        for (size_t k = 0; k < world.size(); ++k) {
            const ProjectedPatch &p = one.patches[k], &q = two.patches[k];
            for (int i = 0; i <= p.patch.p; ++i)
                for (int j = 0; j <= p.patch.q; ++j)
                    for (int d = 0; d < 4; ++d) {
                        CHECK(p.patch.at(i, j)[d] == q.patch.at(i, j)[d]);
                        const HPoint cam = one.frame.to_camera(world[k].at(i, j));
                        CHECK(p.patch.at(i, j)[d] == cam[d]);
                    }
            check_same_forms(p.forms, q.forms);
            check_same_forms(p.forms, patch_forms(p.patch));
            for (int c = 0; c < 3; ++c) CHECK(same(p.hull[c], q.hull[c]));
            for (int c = 0; c < 4; ++c) {
                CHECK(p.slope_s[c] == q.slope_s[c]);
                CHECK(p.slope_t[c] == q.slope_t[c]);
            }
            CHECK(p.shape.dim == q.shape.dim);
            CHECK(p.material == q.material);
        }
    }
}
