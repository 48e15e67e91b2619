// SPDX-License-Identifier: MIT
// The certified Newton solve of a single primary ray never contradicts the
// covering method: a box it declares missed holds no hit, a hit it certifies
// is the only hit in the box and lies in its small box.
#include <seamless/render/pixel_solve.h>
#include <seamless/spline/ray_patch.h>

#include <catch2/catch.hpp>

#include "dome_patch.h"

#include <random>

using namespace seamless;

namespace {

// The dome of dome_patch.h, bulging towards the eye, so that rays near its
// rim meet folds of the silhouette.
ProjectedPatch dome(std::mt19937& rng, double bulge) {
    const BezierPatch b = test::random_dome(rng, bulge);
    ProjectedPatch pp;
    pp.patch = b;
    pp.forms = patch_forms(b);
    pp.hull = enclose_point(pp.forms, ParamBox{});
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
