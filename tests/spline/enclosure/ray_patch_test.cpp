// SPDX-License-Identifier: MIT
#include <seamless/spline/enclosure/ray_patch.h>

#include "spline/patch_samples.h"
#include "test_util.h"

#include <seamless/interval/hansen_sengupta.h>
#include <seamless/model/model.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace seamless;

namespace {

// Gentle height field over [0,1]^2: one hit per ray from above.
BezierPatch height_field(std::mt19937_64& rng, bool rational) {
    std::uniform_real_distribution<double> h(-0.3, 0.3), w(0.5, 2.0);
    BezierPatch b;
    b.p = b.q = 3;
    b.rational = rational;
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 3; ++j)
            b.at(i, j) = HPoint::from({i / 3.0, j / 3.0, h(rng)}, rational ? w(rng) : 1.0);
    return b;
}

// Parabolic trough z = x^2, x = 2s - 1 in [-1, 1], y = 2t - 1.
BezierPatch trough() {
    BezierPatch b;
    b.p = 2;
    b.q = 1;
    const double z[3] = {1, -1, 1};
    for (int i = 0; i <= 2; ++i)
        for (int j = 0; j <= 1; ++j) b.at(i, j) = HPoint::from({i - 1.0, 2.0 * j - 1, z[i]}, 1);
    return b;
}

bool box_contains(const RayPatchHit& h, double s, double t, double slack = 1e-12) {
    return h.box.s.lo() - slack <= s && s <= h.box.s.hi() + slack && h.box.t.lo() - slack <= t &&
           t <= h.box.t.hi() + slack;
}

} // namespace

TEST_CASE("a ray through a known patch point hits once, certified", "[ray_patch][heavy]") {
    std::mt19937_64 rng(41);
    std::uniform_real_distribution<double> u(0.02, 0.98);
    RayPatchStats stats;
    for (int n = 0; n < 200; ++n) {
        const BezierPatch b = height_field(rng, n % 2 == 1);
        const PatchForms f = patch_forms(b);
        const double s = u(rng), t = u(rng);
        const Vec3 P = evaluate(b, s, t).point;
        const Vec3 eye{u(rng), u(rng), 4.0};
        const Ray ray{eye, P - eye};
        const auto hits = intersect(f, ray, {}, &stats);
        INFO("n " << n << " s " << s << " t " << t);
        REQUIRE(hits.size() == 1);
        CHECK(hits[0].unique);
        CHECK(box_contains(hits[0], s, t));
        CHECK(hits[0].box.s.width() <= RayPatchOptions{}.tolerance);
        CHECK(hits[0].q.lo() <= 1 + 1e-12);
        CHECK(hits[0].q.hi() >= 1 - 1e-12);
        const auto nh = nearest_hit(hits);
        REQUIRE(nh);
        CHECK(!nearest_hit(hits, 2.0)); // nothing beyond q = 2
    }
    CHECK(stats.iterations > 0);
    CHECK(stats.unresolved == 0);
    // Hansen-Sengupta converges fast: a handful of steps per ray on average.
    CHECK(stats.iterations < 200 * 40);
}

TEST_CASE("teapot: rays from an eye through patch points", "[ray_patch][heavy]") {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(0.05, 0.95);
    const auto patches = bezier_patches(load_model(test::model_path("teapot.json")));
    RayPatchStats stats;
    for (const auto& b : patches) {
        const PatchForms f = patch_forms(b);
        for (int n = 0; n < 10; ++n) {
            const double s = u(rng), t = u(rng);
            const Vec3 P = evaluate(b, s, t).point;
            const Vec3 eye{7.0, 5.5, 9.0};
            const auto hits = intersect(f, Ray{eye, P - eye}, {}, &stats);
            bool found = false;
            for (const auto& h : hits) found = found || box_contains(h, s, t, 1e-9);
            CHECK(found);
        }
    }
}

TEST_CASE("a ray that misses returns nothing", "[ray_patch]") {
    std::mt19937_64 rng(43);
    const PatchForms f = patch_forms(height_field(rng, false));
    CHECK(intersect(f, Ray{{2.0, 2.0, 3.0}, {0.1, 0.2, -1.0}}).empty()); // passes beside
    CHECK(intersect(f, Ray{{0.5, 0.5, 3.0}, {1.0, 0.0, 0.0}}).empty());  // parallel above
    CHECK(!nearest_hit(f, Ray{{0.5, 0.5, 3.0}, {0.0, 0.0, 1.0}}));       // hit behind origin
    CHECK(intersect(f, Ray{{0.5, 0.5, 3.0}, {0.0, 0.0, 1.0}}).size() == 1);
}

TEST_CASE("a box holding the zero strictly inside certifies uniqueness (Theorem 6 iii)",
          "[ray_patch]") {
    std::mt19937_64 rng(44);
    const BezierPatch b = height_field(rng, true);
    const PatchForms f = patch_forms(b);
    const double s0 = 0.37, t0 = 0.61;
    const Vec3 P = evaluate(b, s0, t0).point;
    // Ray straight down: F = (X - P.x W, Y - P.y W).
    Interval m[2][PowerForm::kMaxDim] = {{1.0, 0.0, 0.0, -P.x}, {0.0, 1.0, 0.0, -P.y}};
    const PowerForm F = combine(f.X, m, 2), Fs = derivative_s(F), Ft = derivative_t(F);
    IVec<2> x{{Interval(s0 - 0.01, s0 + 0.02), Interval(t0 - 0.015, t0 + 0.01)}};
    bool unique = false;
    for (int it = 0; it < 10 && !unique; ++it) {
        const ParamBox box{x[0], x[1]};
        IMat<2> A;
        IVec<2> fc;
        const RVec<2> c = mid(x);
        for (int r = 0; r < 2; ++r) {
            A(r, 0) = horner(Fs, r, box);
            A(r, 1) = horner(Ft, r, box);
            fc[r] = evaluate(F, r, c[0], c[1]);
        }
        const auto step = hansen_sengupta(A, fc, x, c);
        REQUIRE(!step.box.is_empty());
        REQUIRE(step.box[0].contains(s0 - 1e-12)); // zero within rounding of (s0, t0)
        unique = step.unique;
        x = step.box;
    }
    CHECK(unique);
    // And intersect() on the whole patch agrees.
    const auto hits = intersect(f, Ray{{P.x, P.y, 5.0}, {0, 0, -1}});
    REQUIRE(hits.size() == 1);
    CHECK(hits[0].unique);
    CHECK(box_contains(hits[0], s0, t0));
}

TEST_CASE("a ray hitting a folded patch twice returns both", "[ray_patch]") {
    const PatchForms f = patch_forms(trough());
    RayPatchStats stats;
    // z = 0.25 meets z = x^2 at x = -0.5, 0.5, i.e. s = 0.25, 0.75; y = 0.1: t = 0.55.
    const auto hits = intersect(f, Ray{{-3.0, 0.1, 0.25}, {1.0, 0.0, 0.0}}, {}, &stats);
    REQUIRE(hits.size() == 2);
    int found = 0;
    for (const auto& h : hits) {
        CHECK(h.unique);
        found += box_contains(h, 0.25, 0.55) + box_contains(h, 0.75, 0.55);
    }
    CHECK(found == 2);
    const auto nh = nearest_hit(hits);
    REQUIRE(nh);
    CHECK(nh->q.contains(2.5));
    CHECK(box_contains(*nh, 0.25, 0.55));
}

TEST_CASE("grazing rays near the silhouette", "[ray_patch]") {
    const PatchForms f = patch_forms(trough());
    for (double z : {1e-4, 1e-8, 0.0}) {
        RayPatchStats stats;
        const auto hits = intersect(f, Ray{{-3.0, 0.1, z}, {1.0, 0.0, 0.0}}, {}, &stats);
        const double dx = std::sqrt(z) / 2; // s = 0.5 -+ sqrt(z) / 2
        REQUIRE(!hits.empty());
        for (double s : {0.5 - dx, 0.5 + dx}) {
            bool found = false;
            for (const auto& h : hits) found = found || box_contains(h, s, 0.55, 1e-9);
            INFO("z " << z << " s " << s);
            CHECK(found);
        }
        if (z >= 1e-4) { // well separated: both certified
            CHECK(hits.size() == 2);
            for (const auto& h : hits) CHECK(h.unique);
        }
        CHECK(stats.boxes < RayPatchOptions{}.max_boxes);
    }
    // Just above the bottom of the trough: a miss.
    CHECK(intersect(f, Ray{{-3.0, 0.1, -1e-6}, {1.0, 0.0, 0.0}}).empty());
}

TEST_CASE("a pole (collapsed edge) of the teapot still works", "[ray_patch][heavy]") {
    const auto patches = bezier_patches(load_model(test::model_path("teapot.json")));
    int poles = 0;
    for (const auto& b : patches) {
        // Collapsed edge s = 0: every control point of row 0 is the same.
        bool pole = true;
        for (int j = 1; j <= b.q; ++j) pole = pole && b.point(0, j) == b.point(0, 0);
        if (!pole) continue;
        ++poles;
        const PatchForms f = patch_forms(b);
        const Vec3 eye{2.0, 3.0, 8.0};
        for (double s : {0.3, 0.02}) {
            const double t = 0.4;
            const Vec3 P = evaluate(b, s, t).point;
            const auto hits = intersect(f, Ray{eye, P - eye});
            bool found = false;
            for (const auto& h : hits) found = found || box_contains(h, s, t, 1e-9);
            CHECK(found);
        }
        // A ray through the pole itself: some box reaches s = 0 with q near 1.
        RayPatchStats stats;
        const Vec3 pole_point = b.point(0, 0);
        const auto hits = intersect(f, Ray{eye, pole_point - eye}, {}, &stats);
        bool at_pole = false;
        for (const auto& h : hits) at_pole = at_pole || (h.box.s.lo() <= 1e-9 && h.q.contains(1.0));
        CHECK(at_pole);
    }
    CHECK(poles > 0);
}

TEST_CASE("a start box restricts the search", "[ray_patch]") {
    const PatchForms f = patch_forms(trough());
    const Ray ray{{-3.0, 0.1, 0.25}, {1.0, 0.0, 0.0}};
    std::vector<RayPatchHit> hits;
    intersect(f, ray, ParamBox{{0.5, 1.0}, {0.0, 1.0}}, hits);
    REQUIRE(hits.size() == 1);
    CHECK(hits[0].unique);
    CHECK(box_contains(hits[0], 0.75, 0.55));
    hits.clear();
    intersect(f, ray, ParamBox{{0.3, 0.7}, {0.0, 1.0}}, hits);
    CHECK(hits.empty());
}
