// SPDX-License-Identifier: MIT
// The pixels of a small sub-screen solved with shared marks (SharedMarks)
// agree with each pixel solved alone, bit for bit; the marks' depth order and
// diagonal bounds never drop a hit. (Certified Newton itself:
// certified_newton_test.cpp.)
#include <seamless/render/pixels/pixel_solve.h>
#include <seamless/render/scene/scene.h>
#include <seamless/render/subscreen/shared_marks.h>
#include <seamless/spline/enclosure/ray_patch.h>

#include <catch2/catch.hpp>

#include "test_util.h"

#include <random>

using namespace seamless;

namespace {

// The teapot at 160 x 120 with every patch whole as a mark (many hold a
// silhouette, so SharedMarks bisects them), and the marks a sub-screen's rays may meet.
struct TeapotMarks {
    static constexpr int W = 160, H = 120;
    ProjectedScene ps;
    SubpatchArena coefs;
    std::vector<Mark> all;
    TeapotMarks()
        : ps(project_scene(load_scene(test::data_dir() / "scenes" / "teapot.json"), W, H)) {
        for (size_t k = 0; k < ps.patches.size(); ++k) {
            const ProjectedPatch& pp = ps.patches[k];
            all.push_back(
                whole_patch_mark(static_cast<int>(k), pp.patch, pp.shape, pp.hull, coefs));
        }
    }
    // Pixels x0..x1, y0..y1: their screen intervals aB, bB and marks.
    std::vector<Mark> meeting(int x0, int y0, int x1, int y1, Interval& aB, Interval& bB) const {
        aB = {ps.frame.screen_a(x0 + 0.5), ps.frame.screen_a(x1 + 0.5)};
        bB = {ps.frame.screen_b(y0 + 0.5), ps.frame.screen_b(y1 + 0.5)};
        std::vector<Mark> marks;
        for (const Mark& m : all)
            if (may_meet(m, aB, bB)) marks.push_back(m);
        return marks;
    }
    // `count` random draws of a w x h sub-screen (x0 in 0..W-w-1, y0 alike,
    // one seeded generator): f(n, x0, y0, marks, aB, bB) for each that some
    // mark may meet; the subpatches appended while f runs are dropped after it.
    template <class F> void random_subscreens(unsigned seed, int count, int w, int h, F&& f) {
        std::mt19937 rng(seed);
        std::uniform_int_distribution<int> X(0, W - w - 1), Y(0, H - h - 1);
        for (int n = 0; n < count; ++n) {
            const int x0 = X(rng), y0 = Y(rng);
            Interval aB, bB;
            const std::vector<Mark> marks = meeting(x0, y0, x0 + w - 1, y0 + h - 1, aB, bB);
            if (marks.empty()) continue;
            const size_t coef_end = coefs.size();
            f(n, x0, y0, marks, aB, bB);
            coefs.resize(coef_end);
        }
    }
    // `count` random 3 x 3 sub-screens with shared marks: pixel(a, b, marks)
    // for each of their rays in paint order. Returns how many of them had a
    // mark bisected (SharedMarks::refine).
    template <class Pixel>
    int subscreens(unsigned seed, int count, SharedMarks& shared, Pixel&& pixel) {
        int bisected = 0;
        random_subscreens(
            seed, count, 3, 3,
            [&](int, int x0, int y0, const std::vector<Mark>& marks, Interval aB, Interval bB) {
                shared.reset(ps, coefs, marks.data(), marks.size(), aB, bB);
                for (int y = y0; y <= y0 + 2; ++y)
                    for (int x = x0; x <= x0 + 2; ++x)
                        pixel(ps.frame.screen_a(x + 0.5), ps.frame.screen_b(y + 0.5), marks);
                // a silhouette's mark bisected for B
                bisected += shared.size() > marks.size();
            });
        return bisected;
    }
};

// One ray solved with two SharedMarks of the same sub-screen that must agree
// bit for bit (plain: the reference); returns the second's hit.
struct TwinSolves {
    TeapotMarks tm;
    PixelScratch scratch;
    RenderStats st;
    SharedMarks plain, other;
    PixelHit both(double a, double b) {
        const PixelHit h0 = solve_pixel(tm.ps, a, b, plain, scratch, st);
        const PixelHit h1 = solve_pixel(tm.ps, a, b, other, scratch, st);
        REQUIRE(h0.patch == h1.patch);
        if (h1.patch >= 0) {
            CHECK(h0.s == h1.s);
            CHECK(h0.t == h1.t);
            CHECK(h0.q == h1.q);
        }
        return h1;
    }
};

} // namespace

TEST_CASE("Pixels of a small sub-screen solved with shared marks agree with each pixel alone",
          "[pixel_solve][heavy]") {
    // paint_pixels' path (SharedMarks: Newton on the mark's whole box from the
    // previous pixel's hit, the ray's clip only where that fails, one Jacobian
    // per mark for the sub-screen) against every mark solved for the pixel on
    // its own (no clip, no shared Jacobian): the same surface, or background.
    TeapotMarks tm;
    const ProjectedScene& ps = tm.ps;
    PixelScratch scratch;
    SharedMarks shared;
    RenderStats st;
    int surface = 0, background = 0;
    const int bisected = tm.subscreens(17, 120, shared, [&](double a, double b, const auto& marks) {
        const PixelHit h = solve_pixel(ps, a, b, shared, scratch, st);
        const PixelHit ref = solve_pixel(ps, a, b, marks, scratch, st);
        REQUIRE((h.patch < 0) == (ref.patch < 0));
        if (ref.patch < 0) {
            ++background;
            return;
        }
        ++surface;
        // At a seam two patches may share the nearest point: compare points.
        Vec3 P, N, Pr, Nr;
        surface_frame(ps.patches[h.patch].patch, h.s, h.t, P, N);
        surface_frame(ps.patches[ref.patch].patch, ref.s, ref.t, Pr, Nr);
        CHECK(norm(P - Pr) < 1e-6 * norm(Pr));
    });
    CHECK(surface > 200);
    CHECK(bisected > 10);
    CHECK(background > 50);
}

TEST_CASE("Siblings sharing their parent's bisections solve their pixels as each alone",
          "[pixel_solve]") {
    // paint_pixels passes one family id for the four children of a parent
    // (the same marks): a mark bisected for one child is copied for the next
    // instead of bisected again. Hits and marks must be bit for bit those of
    // the children solved without the family.
    TwinSolves twin;
    TeapotMarks& tm = twin.tm;
    const ProjectedScene& ps = tm.ps;
    SharedMarks &plain = twin.plain, &family = twin.other;
    int hits = 0, copied = 0;
    tm.random_subscreens(
        31, 60, 6, 6,
        [&](int n, int x0, int y0, const std::vector<Mark>& marks, Interval, Interval) {
            const size_t coef_end = tm.coefs.size();
            for (int kid = 0; kid < 4; ++kid) {
                const int kx = x0 + 3 * (kid % 2), ky = y0 + 3 * (kid / 2);
                const Interval aB(ps.frame.screen_a(kx + 0.5), ps.frame.screen_a(kx + 2.5));
                const Interval bB(ps.frame.screen_b(ky + 0.5), ps.frame.screen_b(ky + 2.5));
                plain.reset(ps, tm.coefs, marks.data(), marks.size(), aB, bB);
                family.reset(ps, tm.coefs, marks.data(), marks.size(), aB, bB, n);
                for (int y = ky; y <= ky + 2; ++y)
                    for (int x = kx; x <= kx + 2; ++x)
                        hits += twin.both(ps.frame.screen_a(x + 0.5), ps.frame.screen_b(y + 0.5))
                                    .patch >= 0;
                REQUIRE(plain.size() == family.size());
                for (size_t k = 0; k < plain.size(); ++k) {
                    const Mark &m0 = plain.marks()[k], &m1 = family.marks()[k];
                    CHECK(m0.box.s == m1.box.s);
                    CHECK(m0.box.t == m1.box.t);
                    for (int c = 0; c < 3; ++c) CHECK(m0.hull[c] == m1.hull[c]);
                    CHECK(m0.pa == m1.pa);
                    CHECK(m0.pb == m1.pb);
                    const size_t size = ps.patches[m0.patch].shape.size();
                    for (size_t i = 0; i < size; ++i)
                        CHECK(tm.coefs[m0.coef + i] == tm.coefs[m1.coef + i]);
                }
                if (kid == 3) copied += family.copied();
                tm.coefs.resize(coef_end);
            }
        });
    CHECK(hits > 300);
    CHECK(copied > 10);
    // A family id given again with other marks (another list) copies nothing:
    // the pixels of a second sub-screen solve as without the family.
    for (const int x0 : {40, 80}) {
        Interval aB, bB;
        const std::vector<Mark> marks = tm.meeting(x0, 50, x0 + 2, 52, aB, bB);
        const size_t coef_end = tm.coefs.size();
        plain.reset(ps, tm.coefs, marks.data(), marks.size(), aB, bB);
        family.reset(ps, tm.coefs, marks.data(), marks.size(), aB, bB, 999);
        for (int y = 50; y <= 52; ++y)
            for (int x = x0; x <= x0 + 2; ++x)
                twin.both(ps.frame.screen_a(x + 0.5), ps.frame.screen_b(y + 0.5));
        CHECK(family.copied() == 0);
        tm.coefs.resize(coef_end);
    }
}

TEST_CASE("Newton from a kept evaluation at the previous hit runs as from the start point alone",
          "[pixel_solve]") {
    // A hit by certified Newton keeps the certificate's evaluation at
    // Newton's point itself; for other hits paint_pixels hands SharedMarks
    // the patch evaluated at the shaded hit (surface_frame's), and the next
    // ray's Newton run on that mark takes it as its first step's evaluation:
    // the hits must be bit for bit those of the same sub-screens solved
    // without the latter.
    TwinSolves twin;
    TeapotMarks& tm = twin.tm;
    const ProjectedScene& ps = tm.ps;
    SharedMarks &plain = twin.plain, &kept = twin.other;
    int hits = 0, reused = 0;
    tm.random_subscreens(
        23, 120, 4, 3,
        [&](int, int x0, int y0, const std::vector<Mark>& marks, Interval aB, Interval bB) {
            plain.reset(ps, tm.coefs, marks.data(), marks.size(), aB, bB);
            kept.reset(ps, tm.coefs, marks.data(), marks.size(), aB, bB);
            for (int y = y0; y <= y0 + 2; ++y)
                for (int x = x0; x <= x0 + 3; ++x) {
                    const double a = ps.frame.screen_a(x + 0.5), b = ps.frame.screen_b(y + 0.5);
                    bool available = false; // a kept evaluation this ray may start from
                    for (size_t k = 0; k < kept.size(); ++k)
                        available |= kept.at_start(k) != nullptr;
                    reused += available;
                    const PixelHit h1 = twin.both(a, b);
                    if (h1.patch < 0) continue;
                    ++hits;
                    if (h1.mark < 0) continue;
                    if (kept.at_start(h1.mark) == nullptr) { // as paint_pixels
                        Vec3 P, N;
                        SurfacePoint at;
                        surface_frame(ps.patches[h1.patch].patch, h1.s, h1.t, P, N, &at);
                        kept.evaluated(h1.mark, h1.s, h1.t, at);
                    }
                    REQUIRE(kept.at_start(h1.mark) != nullptr);
                }
        });
    CHECK(hits > 300);
    CHECK(reused > 300);
}

TEST_CASE("A mark's kept centre enclosure decides may_hold_zero as the ray's own evaluation",
          "[pixel_solve]") {
    // SharedMarks::centre keeps X, Y, Z at each mark's box centre for all rays
    // of B (recomputed for the halves of a bisected mark): the Hansen-Sengupta
    // step over the box must come out bit for bit as with G evaluated per ray.
    TeapotMarks tm;
    const ProjectedScene& ps = tm.ps;
    PixelScratch scratch;
    SharedMarks shared;
    RenderStats st;
    int compared = 0, misses = 0;
    const int bisected = tm.subscreens(29, 60, shared, [&](double a, double b, const auto&) {
        solve_pixel(ps, a, b, shared, scratch, st); // bisects marks
        for (size_t k = 0; k < shared.size(); ++k) {
            const Mark& m = shared.marks()[k];
            const MarkJacobian& J = shared.jacobian(k);
            RaySystem sys(ps.patches[m.patch], a, b, scratch.sys);
            ParamBox r0, r1;
            const bool own = may_hold_zero(sys, J, m.box, r0, st);
            const bool kept = may_hold_zero(sys, J, m.box, r1, st, shared.centre(k));
            REQUIRE(own == kept);
            ++compared;
            if (!own) {
                ++misses;
                continue;
            }
            CHECK(r0.s == r1.s);
            CHECK(r0.t == r1.t);
        }
    });
    CHECK(compared > 500);
    CHECK(misses > 100);
    CHECK(bisected > 5);
}

TEST_CASE("SharedMarks' depth order holds every mark once, nearest first, after bisections too",
          "[pixel_solve]") {
    // solve_pixel walks the marks a ray may meet in this order (sorted once
    // per B and after each refine instead of per pixel): it must be the sort
    // of all of B's marks, halves included, by (hull[2].lo(), index).
    TeapotMarks tm;
    PixelScratch scratch;
    SharedMarks shared;
    RenderStats st;
    int checked = 0;
    const int bisected = tm.subscreens(31, 60, shared, [&](double a, double b, const auto&) {
        solve_pixel(tm.ps, a, b, shared, scratch, st); // bisects marks
        const auto& order = shared.depth_order();
        REQUIRE(order.size() == shared.size());
        std::vector<int> seen(shared.size(), 0);
        for (size_t i = 0; i < order.size(); ++i) {
            const auto [zlo, k] = order[i];
            REQUIRE(k >= 0);
            REQUIRE(static_cast<size_t>(k) < shared.size());
            ++seen[k];
            CHECK(zlo == shared.marks()[k].hull[2].lo());
            if (i > 0) CHECK(order[i - 1] < order[i]);
        }
        for (const int n : seen) CHECK(n == 1);
        ++checked;
    });
    CHECK(checked > 300);
    CHECK(bisected > 5);
}

TEST_CASE("A mark's diagonal bounds reject only rays that miss it", "[pixel_solve]") {
    // After a miss, SharedMarks::may_meet_ray also bounds a + b and a - b by
    // the mark's (x + y) / z and (x - y) / z: a ray it rejects inside the
    // mark's screen rectangle must meet the patch nowhere in the mark's box
    // (the covering method of ray_patch.h as the reference).
    TeapotMarks tm;
    PixelScratch scratch;
    SharedMarks shared;
    RenderStats st;
    std::mt19937 rng(37);
    std::uniform_real_distribution<double> U(-1.5, 1.5);
    const double pa = 2.0 * tm.ps.frame.tan_half * tm.ps.frame.aspect / tm.W;
    const double pb = 2.0 * tm.ps.frame.tan_half / tm.H;
    int diagonal = 0, compared = 0;
    tm.subscreens(41, 80, shared, [&](double a, double b, const auto&) {
        solve_pixel(tm.ps, a, b, shared, scratch, st); // marks missed
        for (int r = 0; r < 4; ++r) {
            const double ra = a + U(rng) * pa, rb = b + U(rng) * pb;
            for (size_t k = 0; k < shared.size(); ++k) {
                const Mark& m = shared.marks()[k];
                if (shared.may_meet_ray(k, ra, rb) || !may_meet(m, Interval(ra), Interval(rb)))
                    continue;
                ++diagonal; // inside the rectangle, rejected diagonally
                std::vector<RayPatchHit> all;
                intersect(tm.ps.patches[m.patch].forms, ProjectedScene::primary_ray(ra, rb), m.box,
                          all, RayPatchOptions{});
                CHECK(all.empty());
                ++compared;
            }
        }
    });
    CHECK(diagonal > 100);
    CHECK(compared == diagonal);
}
