// SPDX-License-Identifier: MIT
// The certified Newton solve of a single primary ray never contradicts the
// covering method: a box it declares missed holds no hit, a hit it certifies
// is the only hit in the box and lies in its small box.
#include <seamless/render/pixels/certified_newton.h>
#include <seamless/spline/enclosure/ray_patch.h>

#include <catch2/catch.hpp>

#include "render/dome_patch.h"

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

} // namespace

TEST_CASE("Certified Newton agrees with the covering method", "[certified_newton][heavy]") {
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
        CertifiedHit h;
        const NewtonOutcome r = newton_certified(sys, box, h, st);
        check_outcome(pp, a, b, box, r, h.box, h.q, nullptr, counts);
    }
    CHECK(counts[0] > 50);
    CHECK(counts[1] > 50);
}

TEST_CASE("Certified Newton with a sub-screen's Jacobian: no hit lost, none invented",
          "[certified_newton]") {
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
        ParamBox rest;
        CertifiedHit h;
        const NewtonOutcome r = newton_certified(sys, box, h, st, &J, &rest);
        check_outcome(pp, a, b, box, r, h.box, h.q, &rest, counts);
    }
    CHECK(counts[0] > 50);
    CHECK(counts[1] > 50);
}

TEST_CASE("Certified Newton's depth encloses the patch's depth, polynomial and rational",
          "[certified_newton]") {
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
        CertifiedHit h;
        if (newton_certified(sys, box, h, st, nullptr) != NewtonOutcome::hit) continue;
        const ParamBox& hb = h.box;
        const Interval& q = h.q;
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

TEST_CASE("Krawczyk's test certifies only where the covering method finds the one hit",
          "[certified_newton]") {
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
          "[certified_newton][heavy]") {
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
          "[certified_newton]") {
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
          "[certified_newton]") {
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
