// SPDX-License-Identifier: MIT
// The certified Newton solve of a single primary ray never contradicts the
// covering method: a box it declares missed holds no hit, a hit it certifies
// is the only hit in the box and lies in its small box.
#include <seamless/render/pixel_solve.h>
#include <seamless/render/scene.h>
#include <seamless/render/shared_marks.h>
#include <seamless/spline/ray_patch.h>

#include <catch2/catch.hpp>

#include "dome_patch.h"
#include "test_util.h"

#include <random>

using namespace seamless;

namespace {

// The dome of dome_patch.h, bulging towards the eye, so that rays near its
// rim meet folds of the silhouette.
ProjectedPatch dome(std::mt19937& rng, double bulge) {
    const BezierPatch b = test::random_dome(rng, bulge);
    ProjectedPatch pp;
    set_camera_patch(pp, b);
    return pp;
}

// Checks one certified Newton outcome against the covering method of
// ray_patch.h: a miss holds no hit, a hit is the only one and lies in the
// small box, an undecided solve's rest (when given) keeps every hit.
// counts: hits, misses, undecided.
void check_outcome(const ProjectedPatch& pp, double a, double b, const ParamBox& box,
                   NewtonOutcome r, const ParamBox& hb, Interval q, const ParamBox* rest,
                   int counts[3]) {
    std::vector<RayPatchHit> all;
    intersect(pp.forms, ProjectedScene::primary_ray(a, b), box, all, RayPatchOptions{});
    if (r == NewtonOutcome::miss) {
        ++counts[1];
        CHECK(all.empty());
    } else if (r == NewtonOutcome::hit) {
        ++counts[0];
        REQUIRE(all.size() == 1);
        CHECK(hb.s.overlaps(all[0].box.s));
        CHECK(hb.t.overlaps(all[0].box.t));
        CHECK(hb.s.width() < 1e-8);
        CHECK(q.overlaps(all[0].q));
    } else {
        ++counts[2];
        if (rest)
            for (const RayPatchHit& h : all) {
                CHECK(rest->s.overlaps(h.box.s));
                CHECK(rest->t.overlaps(h.box.t));
            }
    }
}

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
        const PixelHit h0 = solve_pixel(tm.ps, a, b, nullptr, 0, scratch, st, &plain);
        const PixelHit h1 = solve_pixel(tm.ps, a, b, nullptr, 0, scratch, st, &other);
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

TEST_CASE("Certified Newton agrees with the covering method", "[pixel_solve]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> U(-0.25, 0.25), S(0.0, 1.0);
    int counts[3] = {0, 0, 0}; // hits, misses, undecided
    for (int n = 0; n < 400; ++n) {
        const ProjectedPatch pp = dome(rng, n % 2 ? 0.8 : 3.0);
        // A random sub-box of [0,1]^2, sometimes the whole square.
        ParamBox box;
        if (n % 3) {
            const double s0 = S(rng), t0 = S(rng), w = 0.05 + 0.5 * S(rng);
            box = {Interval(s0 * (1 - w), s0 * (1 - w) + w),
                   Interval(t0 * (1 - w), t0 * (1 - w) + w)};
        }
        // Half the rays aimed at a point of the patch inside the box, half at random.
        double a = U(rng), b = U(rng);
        if (n % 4 < 2) {
            const double s = box.s.lo() + S(rng) * (box.s.hi() - box.s.lo());
            const double t = box.t.lo() + S(rng) * (box.t.hi() - box.t.lo());
            const Vec3 P = evaluate(pp.patch, s, t).point;
            a = P.x / P.z;
            b = P.y / P.z;
        }
        ClusterSystem storage;
        RaySystem sys(pp, a, b, storage);
        RenderStats st;
        ParamBox hb;
        Interval q;
        const NewtonOutcome r = newton_certified(pp, a, b, box, sys, hb, q, st);
        check_outcome(pp, a, b, box, r, hb, q, nullptr, counts);
    }
    CHECK(counts[0] > 50);
    CHECK(counts[1] > 50);
}

TEST_CASE("Certified Newton with a sub-screen's Jacobian: no hit lost, none invented",
          "[pixel_solve]") {
    // The pixels of a small sub-screen share one Jacobian per mark, enclosed
    // for the rays of the whole sub-screen; an undecided solve hands back the
    // part of the box that may still hold the hit.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(-0.25, 0.25), S(0.0, 1.0);
    int counts[3] = {0, 0, 0}; // hits, misses, undecided
    for (int n = 0; n < 400; ++n) {
        const ProjectedPatch pp = dome(rng, n % 2 ? 0.8 : 3.0);
        const double s0 = S(rng), t0 = S(rng), w = 0.05 + 0.5 * S(rng);
        const ParamBox box{Interval(s0 * (1 - w), s0 * (1 - w) + w),
                           Interval(t0 * (1 - w), t0 * (1 - w) + w)};
        double a = U(rng), b = U(rng);
        if (n % 4 < 2) {
            const Vec3 P =
                evaluate(pp.patch, box.s.lo() + S(rng) * w, box.t.lo() + S(rng) * w).point;
            a = P.x / P.z;
            b = P.y / P.z;
        }
        // The sub-screen: a few pixels around the ray.
        const double d = 0.002 * S(rng);
        ClusterSystem sub, storage;
        cluster_system(pp.forms, Interval(a - d, a + d), Interval(b - d, b + d), sub);
        const MarkJacobian J = mark_jacobian(sub, box);
        RaySystem sys(pp, a, b, storage);
        RenderStats st;
        ParamBox hb, rest;
        Interval q;
        const NewtonOutcome r = newton_certified(pp, a, b, box, sys, hb, q, st, &J, &rest);
        check_outcome(pp, a, b, box, r, hb, q, &rest, counts);
    }
    CHECK(counts[0] > 50);
    CHECK(counts[1] > 50);
}

TEST_CASE("Certified Newton's depth encloses the patch's depth, polynomial and rational",
          "[pixel_solve]") {
    // The depth of a certified hit comes from the mean value theorem about
    // the hit box's centre (not a range enclosure): it must hold the camera z
    // of the surface at every point of the hit box, also where W varies.
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> S(0.0, 1.0), Wt(0.5, 2.0);
    int hits = 0;
    for (int n = 0; n < 200; ++n) {
        ProjectedPatch pp = dome(rng, n % 2 ? 0.8 : 3.0);
        if (n % 2) { // rational: the same points with weights in [0.5, 2]
            BezierPatch r = pp.patch;
            for (int i = 0; i <= r.p; ++i)
                for (int j = 0; j <= r.q; ++j)
                    r.at(i, j) = HPoint::from(r.at(i, j).point(), Wt(rng));
            r.rational = true;
            set_camera_patch(pp, r);
        }
        const double s0 = S(rng), t0 = S(rng);
        const Vec3 P = evaluate(pp.patch, s0, t0).point;
        const double a = P.x / P.z, b = P.y / P.z;
        const ParamBox box{intersect(Interval(s0 - 0.05, s0 + 0.05), Interval(0.0, 1.0)),
                           intersect(Interval(t0 - 0.05, t0 + 0.05), Interval(0.0, 1.0))};
        ClusterSystem storage;
        RaySystem sys(pp, a, b, storage);
        RenderStats st;
        ParamBox hb;
        Interval q;
        if (newton_certified(pp, a, b, box, sys, hb, q, st, nullptr) != NewtonOutcome::hit)
            continue;
        ++hits;
        for (double s : {hb.s.lo(), hb.s.mid(), hb.s.hi()})
            for (double t : {hb.t.lo(), hb.t.mid(), hb.t.hi()}) {
                Interval X[4];
                enclose_homogeneous(pp.patch, s, t, 4, X);
                CHECK(q.overlaps(X[2] / X[3])); // X[3] = W > 0 for these weights
            }
        // Narrow enough to order hits and drop marks beyond them (a coarse
        // derivative bound times the hit box's width of about 1e-9).
        CHECK(q.width() < 1e-5 * q.mag());
    }
    CHECK(hits > 50);
}

TEST_CASE("Pixels of a small sub-screen solved with shared marks agree with each pixel alone",
          "[pixel_solve]") {
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
        const PixelHit h = solve_pixel(ps, a, b, nullptr, 0, scratch, st, &shared);
        const PixelHit ref = solve_pixel(ps, a, b, marks.data(), marks.size(), scratch, st);
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
    // paint_pixels hands SharedMarks the patch evaluated at each shaded hit
    // (surface_frame's), and the next ray's Newton run on that mark takes it
    // as its first step's evaluation: the hits must be bit for bit those of
    // the same sub-screens solved without it.
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
                    Vec3 P, N;
                    SurfacePoint at;
                    surface_frame(ps.patches[h1.patch].patch, h1.s, h1.t, P, N, &at);
                    kept.evaluated(h1.mark, h1.s, h1.t, at);
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
        solve_pixel(ps, a, b, nullptr, 0, scratch, st, &shared); // bisects marks
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

TEST_CASE("Krawczyk's test certifies only where the covering method finds the one hit",
          "[pixel_solve]") {
    // Newton's point on a dome patch, a small box Y around it (inflated by
    // 1e-9 as newton_hit does, or by more), and the sub-screen's Jacobian:
    // a certified K holds the only hit in Y, and the Hansen-Sengupta step on
    // the same Y proves it too (it is at least as strong).
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> S(0.0, 1.0);
    int certified = 0, tried = 0;
    for (int n = 0; n < 400; ++n) {
        const ProjectedPatch pp = dome(rng, n % 2 ? 0.8 : 3.0);
        const double s0 = S(rng), t0 = S(rng), w = 0.02 + 0.2 * S(rng);
        const ParamBox box{Interval(s0 * (1 - w), s0 * (1 - w) + w),
                           Interval(t0 * (1 - w), t0 * (1 - w) + w)};
        const double s = box.s.lo() + S(rng) * w, t = box.t.lo() + S(rng) * w;
        const Vec3 P = evaluate(pp.patch, s, t).point;
        const double a = P.x / P.z, b = P.y / P.z;
        const double d = 0.002 * S(rng);
        ClusterSystem sub, storage;
        cluster_system(pp.forms, Interval(a - d, a + d), Interval(b - d, b + d), sub);
        const MarkJacobian J = mark_jacobian(sub, box);
        // Newton's point: the exact (s, t) moved by up to e (far beyond the box for large e).
        const double e = n % 3 == 0 ? 1e-12 : (n % 3 == 1 ? 1e-10 : 1e-7);
        const double cs = std::clamp(s + e * (2 * S(rng) - 1), box.s.lo(), box.s.hi());
        const double ct = std::clamp(t + e * (2 * S(rng) - 1), box.t.lo(), box.t.hi());
        const double r = n % 5 == 0 ? 1e-6 : 1e-9;
        const IVec<2> Y{{intersect(Interval(cs - r, cs + r), box.s),
                         intersect(Interval(ct - r, ct + r), box.t)}};
        RaySystem sys(pp, a, b, storage);
        const IVec<2> F = sys.at(cs, ct);
        ParamBox hit;
        ++tried;
        if (!krawczyk_hit(J, F, Y, RVec<2>{cs, ct}, hit)) continue;
        ++certified;
        CHECK(J.regular);
        CHECK(Y[0].contains(hit.s));
        CHECK(Y[1].contains(hit.t));
        std::vector<RayPatchHit> all;
        intersect(pp.forms, ProjectedScene::primary_ray(a, b), ParamBox{Y[0], Y[1]}, all,
                  RayPatchOptions{});
        REQUIRE(all.size() == 1);
        CHECK(hit.s.overlaps(all[0].box.s));
        CHECK(hit.t.overlaps(all[0].box.t));
        const HansenSenguptaStep<2> hs = J.step(F, Y, RVec<2>{cs, ct});
        CHECK(hs.unique);
    }
    CHECK(certified > 100);
    CHECK(certified < tried); // Newton's point 1e-7 off with Y of 1e-9: no certificate
}

TEST_CASE("A mark Jacobian's C A and |I - C A| enclose every matrix of A preconditioned",
          "[pixel_solve]") {
    // C A is formed in doubles with a relative slack: for matrices drawn from
    // A (corners and inner points), C A~ lies in CA and |delta - (C A~)| <= E.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> U(-1.0, 1.0), W(0.0, 1.0);
    int regular = 0;
    for (int n = 0; n < 2000; ++n) {
        const double scale = std::ldexp(1.0, static_cast<int>(40 * U(rng)));
        IMat<2> A;
        for (int i = 0; i < 2; ++i)
            for (int k = 0; k < 2; ++k) {
                const double m = scale * (U(rng) + (i == k ? 2.0 : 0.0));
                const double r = scale * 0.3 * W(rng) * W(rng);
                A(i, k) = Interval(m - r, m + r);
            }
        const MarkJacobian J = mark_jacobian(A);
        if (!J.preconditioned) continue;
        regular += J.regular ? 1 : 0;
        for (int sample = 0; sample < 8; ++sample) {
            double a[4];
            for (int e = 0; e < 4; ++e) {
                const Interval x = A.a[e];
                const double f = sample < 4 ? ((sample >> (e % 2)) & 1) : W(rng);
                a[e] = std::clamp(x.lo() + f * (x.hi() - x.lo()), x.lo(), x.hi());
            }
            for (int i = 0; i < 2; ++i)
                for (int k = 0; k < 2; ++k) {
                    // C A~ entry, enclosed with outward rounding.
                    const Interval ca = Interval(J.C[i * 2]) * Interval(a[k]) +
                                        Interval(J.C[i * 2 + 1]) * Interval(a[2 + k]);
                    CHECK(J.CA(i, k).overlaps(ca));
                    CHECK((Interval(i == k ? 1.0 : 0.0) - ca).lo() <= J.E[i * 2 + k]);
                    CHECK(-(Interval(i == k ? 1.0 : 0.0) - ca).hi() <= J.E[i * 2 + k]);
                }
        }
    }
    CHECK(regular > 100);
}

TEST_CASE("G at an enclosed point, formed in doubles, holds the interval operations' enclosure",
          "[pixel_solve]") {
    // RaySystem::at widens bounds formed in doubles by a relative 2e-15, far
    // more than the ulp per operation that interval arithmetic adds: it holds
    // X - a Z as the interval operations enclose it, at any magnitude.
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> U(-1.0, 1.0), W(0.0, 1.0);
    const ProjectedPatch pp = dome(rng, 1.0);
    ClusterSystem storage;
    for (int n = 0; n < 20000; ++n) {
        const double a = U(rng) * std::ldexp(1.0, static_cast<int>(8 * U(rng)));
        const double b = U(rng);
        const RaySystem sys(pp, a, b, storage);
        Interval X[3];
        for (Interval& x : X) {
            const double m = U(rng) * std::ldexp(1.0, static_cast<int>(300 * U(rng)));
            const double r = std::abs(m) * 1e-12 * W(rng);
            x = Interval(m - r, m + r);
        }
        const IVec<2> G = sys.at(X);
        CHECK(G[0].contains(X[0] - Interval(a) * X[2]));
        CHECK(G[1].contains(X[1] - Interval(b) * X[2]));
    }
}

TEST_CASE("A RaySystem reuses forms built in its storage only for the same patch and ray",
          "[pixel_solve]") {
    // Marks of one patch solved for one ray share the ray's power forms
    // (PixelScratch::sys_of); another ray or patch builds its own.
    std::mt19937 rng(23);
    const ProjectedPatch p0 = dome(rng, 0.8), p1 = dome(rng, 3.0);
    const ParamBox box{Interval(0.2, 0.6), Interval(0.3, 0.5)};
    auto same = [&](const MarkJacobian& x, const MarkJacobian& y) {
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j)
                if (!(x.A(i, j).lo() == y.A(i, j).lo() && x.A(i, j).hi() == y.A(i, j).hi()))
                    return false;
        return true;
    };
    auto alone = [&](const ProjectedPatch& pp, double a, double b) {
        ClusterSystem own;
        RaySystem sys(pp, a, b, own);
        return mark_jacobian(sys.forms(), box);
    };
    ClusterSystem storage;
    FormsKey of;
    const struct {
        const ProjectedPatch* pp;
        double a, b;
    } rays[] = {{&p0, 0.01, -0.02}, {&p0, 0.01, -0.02}, {&p0, 0.03, -0.02},
                {&p1, 0.03, -0.02}, {&p1, 0.03, 0.05},  {&p0, 0.01, -0.02}};
    for (const auto& r : rays) {
        RaySystem sys(*r.pp, r.a, r.b, storage, of);
        CHECK(same(mark_jacobian(sys.forms(), box), alone(*r.pp, r.a, r.b)));
        CHECK(of.pp == r.pp);
    }
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
        solve_pixel(tm.ps, a, b, nullptr, 0, scratch, st, &shared); // bisects marks
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
        solve_pixel(tm.ps, a, b, nullptr, 0, scratch, st, &shared); // marks missed
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
