// SPDX-License-Identifier: MIT
// Theorem 10 narrowing and the cluster certificate never lose a hit: every ray
// of a sampled cluster that meets the patch does so inside the narrowed box,
// and a certified box holds exactly one hit of every ray.
#include <seamless/render/scene/projection.h>
#include <seamless/render/subscreen/bezier_clip.h>
#include <seamless/render/subscreen/mark.h>
#include <seamless/render/subscreen/primary_cluster.h>
#include <seamless/spline/enclosure/ray_patch.h>

#include <catch2/catch.hpp>

#include "render/dome_patch.h"

#include <random>
#include <vector>

using namespace seamless;

namespace {

// The dome of dome_patch.h with its inner control points 0.8 nearer the eye.
BezierPatch dome(std::mt19937& rng) {
    return test::random_dome(rng, 0.8);
}

// A cluster of primary rays: screen intervals [a] x [b] of width up to 0.01.
void random_cluster(std::mt19937& rng, Interval& a, Interval& b) {
    std::uniform_real_distribution<double> U(-0.15, 0.15), W(0.0, 0.01);
    const double a0 = U(rng), b0 = U(rng);
    a = Interval(a0, a0 + W(rng));
    b = Interval(b0, b0 + W(rng));
}

// 20 random rays of the cluster: ray(ra, rb, hits) with every hit of the ray
// through (ra, rb).
template <class RayHits>
void for_sampled_rays(std::mt19937& rng, const PatchForms& f, Interval a, Interval b, RayHits ray) {
    std::uniform_real_distribution<double> A(a.lo(), a.hi()), B(b.lo(), b.hi());
    for (int k = 0; k < 20; ++k) {
        const double ra = A(rng), rb = B(rng);
        ray(ra, rb, intersect(f, Ray{{0, 0, 0}, {ra, rb, 1}}));
    }
}

} // namespace

TEST_CASE("Theorem 10 narrowing keeps every hit of the cluster", "[primary_cluster][heavy]") {
    std::mt19937 rng(21);
    int certified = 0, narrowed = 0;
    for (int n = 0; n < 200; ++n) {
        const BezierPatch b = dome(rng);
        const PatchForms f = patch_forms(b);
        Interval a, bb;
        random_cluster(rng, a, bb);
        ClusterSystem sys;
        cluster_system(f, a, bb, sys);
        ParamBox box;
        const bool meets = narrow(sys, box);
        narrowed += meets && box.s.width() < 0.5;
        ParamBox cbox = box;
        const bool cert = meets && certify_cluster(sys, cbox);
        certified += cert;
        for_sampled_rays(rng, f, a, bb, [&](double, double, const auto& hits) {
            for (const RayPatchHit& h : hits) {
                if (!h.unique) continue;
                const double s = h.box.s.mid(), t = h.box.t.mid();
                CHECK(meets);
                CHECK(box.s.contains(s));
                CHECK(box.t.contains(t));
                if (cert) {
                    CHECK(cbox.s.contains(s));
                    CHECK(cbox.t.contains(t));
                }
            }
            if (cert) CHECK(hits.size() == 1);
        });
    }
    CHECK(narrowed > 100);
    CHECK(certified > 100);
}

namespace {

// A fold: X(s) rises and falls back (its control x -0.2, 0.9, 0.9, -0.2), so
// the rays through a in about (0, 0.1) meet it twice, once on either side of
// the midline s = 1/2, where separation (remark 3) can split a mark.
BezierPatch fold(std::mt19937& rng) {
    std::uniform_real_distribution<double> J(-0.03, 0.03);
    const double x[4] = {-0.2, 0.9, 0.9, -0.2};
    BezierPatch b;
    b.p = b.q = 3;
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 3; ++j)
            b.at(i, j) =
                HPoint::from({x[i] + J(rng), -1 + 2.0 * j / 3 + J(rng), 5 + 0.3 * i + J(rng)}, 1.0);
    return b;
}

// Clusters in the fold's double-hit band.
void fold_cluster(std::mt19937& rng, Interval& a, Interval& b) {
    std::uniform_real_distribution<double> U(0.0, 0.08), V(-0.15, 0.15), W(0.0, 0.01);
    const double a0 = U(rng), b0 = V(rng);
    a = Interval(a0, a0 + W(rng));
    b = Interval(b0, b0 + W(rng));
}

struct NarrowCounts {
    int narrowed = 0, separated = 0;
};

// Narrowing, bisection and separation of random patches against random
// clusters: every sampled hit inside the start box stays in the narrowed box,
// its enclosures, and one of the separated parts.
template <class MakePatch, class MakeCluster>
NarrowCounts narrow_and_separate(std::mt19937& rng, MakePatch make_patch,
                                 MakeCluster make_cluster) {
    NarrowCounts c;
    for (int n = 0; n < 200; ++n) {
        const BezierPatch b = make_patch(rng);
        const PatchForms f = patch_forms(b);
        const SubpatchShape sh = subpatch_shape(b);
        SubpatchArena arena(sh.size());
        control_coefficients(b, sh, arena.data());
        Interval a, bb;
        make_cluster(rng, a, bb);
        Mark m{0, ParamBox{}, IVec3{}, 0};
        // A start box of a quarter or the whole patch, as a child sub-screen's mark.
        if (n % 2) {
            Mark half[2];
            bisect_mark(arena, sh, m, n % 4 == 1 ? 0 : 1, half);
            m = half[n % 3 == 0 ? 0 : 1];
        }
        const ParamBox start = m.box;
        IMat<2> D;
        const bool meets = narrow_mark(arena, sh, a, bb, m, &D);
        c.narrowed += meets && m.box.s.width() * m.box.t.width() < 0.25 * start.s.width();
        Mark parts[2];
        int np = 0;
        if (meets) {
            update_enclosures(arena, sh, m);
            np = separate_mark(arena, sh, a, bb, m, parts);
            c.separated += np == 2;
        }
        for_sampled_rays(rng, f, a, bb, [&](double ra, double rb, const auto& hits) {
            for (const RayPatchHit& h : hits) {
                if (!h.unique) continue;
                const double s = h.box.s.mid(), t = h.box.t.mid();
                if (!start.s.contains(s) || !start.t.contains(t)) continue;
                CHECK(meets);
                CHECK(m.box.s.contains(s));
                CHECK(m.box.t.contains(t));
                CHECK(m.pa.contains(ra));
                CHECK(m.pb.contains(rb));
                CHECK(m.hull[2].contains(h.q.mid()));
                bool in_part = false;
                for (int i = 0; i < np; ++i)
                    in_part = in_part || (parts[i].box.s.contains(s) && parts[i].box.t.contains(t));
                CHECK(in_part);
            }
        });
    }
    return c;
}

} // namespace

TEST_CASE("Subpatch narrowing, bisection and separation keep every hit",
          "[primary_cluster][heavy]") {
    std::mt19937 rng(33);
    const NarrowCounts domes = narrow_and_separate(rng, dome, random_cluster);
    CHECK(domes.narrowed > 50);
    // Folds, whose rays meet them twice: separation splits marks, and both
    // parts keep their hits (domes are never separated).
    const NarrowCounts folds = narrow_and_separate(rng, fold, fold_cluster);
    CHECK(folds.separated > 20);
}

TEST_CASE("A mark's plane range holds n . X of every point over its box", "[primary_cluster]") {
    std::mt19937 rng(41);
    std::uniform_real_distribution<double> U(-1, 1), Wt(0.5, 2.0), F(0.0, 1.0);
    int narrower = 0;
    for (int n = 0; n < 100; ++n) {
        BezierPatch b = dome(rng);
        if (n % 2) { // rational: every control point with its own weight
            b.rational = true;
            for (int i = 0; i <= 3; ++i)
                for (int j = 0; j <= 3; ++j) b.at(i, j) = HPoint::from(b.point(i, j), Wt(rng));
        }
        const SubpatchShape sh = subpatch_shape(b);
        SubpatchArena arena(sh.size());
        control_coefficients(b, sh, arena.data());
        const Vec3 normal{U(rng), U(rng), U(rng)};
        Mark m{0, ParamBox{}, IVec3{}, 0};
        const Interval whole = plane_range(arena, sh, m, normal);
        for (int k = 0; k < 1 + n % 4; ++k) { // a sub-box, as a deeper sub-screen's mark
            Mark half[2];
            bisect_mark(arena, sh, m, k % 2, half);
            m = half[(n >> k) & 1];
        }
        const Interval r = plane_range(arena, sh, m, normal);
        narrower += r.width() < 0.75 * whole.width();
        for (int k = 0; k < 50; ++k) {
            const double s = m.box.s.lo() + F(rng) * m.box.s.width();
            const double t = m.box.t.lo() + F(rng) * m.box.t.width();
            Vec3 P, N;
            surface_frame(b, s, t, P, N);
            CHECK(r.contains(dot(normal, P)));
        }
    }
    CHECK(narrower > 50);
}

TEST_CASE("The certificate in pieces is certify_cluster, and fails where a corner ray clips away",
          "[primary_cluster]") {
    std::mt19937 rng(33);
    std::uniform_real_distribution<double> U(-0.4, 0.4), W(0.0, 0.05);
    int certified = 0, corner_missed = 0;
    for (int n = 0; n < 300; ++n) {
        const BezierPatch b = dome(rng);
        const PatchForms f = patch_forms(b);
        const SubpatchShape sh = subpatch_shape(b);
        std::vector<Interval> c(sh.size());
        control_coefficients(b, sh, c.data());
        const double a0 = U(rng), b0 = U(rng);
        const Interval a(a0, a0 + W(rng)), bb(b0, b0 + W(rng));
        ClusterSystem sys;
        cluster_system(f, a, bb, sys);
        ParamBox box;
        if (!narrow(sys, box)) continue;
        ParamBox whole = box, pieces = box;
        long long steps_whole = 0, steps_pieces = 0;
        const bool cert = certify_cluster(sys, whole, &steps_whole);
        IVec<2> x = cluster_start(pieces);
        ClusterCertificate r = certify_steps(sys, x, pieces, 1, &steps_pieces);
        if (r == ClusterCertificate::open)
            r = certify_steps(sys, x, pieces, kClusterCertifySteps - 1, &steps_pieces);
        CHECK((r == ClusterCertificate::proven) == cert);
        CHECK(steps_pieces == steps_whole);
        if (cert) {
            CHECK(pieces.s.lo() == whole.s.lo());
            CHECK(pieces.s.hi() == whole.s.hi());
            CHECK(pieces.t.lo() == whole.t.lo());
            CHECK(pieces.t.hi() == whole.t.hi());
        }
        certified += cert;
        // A corner ray that one Bezier clip of the whole patch excludes has
        // no hit: the cluster cannot be certified (cluster_attempt.cpp).
        bool missed = false;
        for (double ca : {a.lo(), a.hi()})
            for (double cb : {bb.lo(), bb.hi()}) {
                Interval u, v;
                missed |= !clip_cluster(c.data(), sh, Interval(ca), Interval(cb), u, v);
            }
        corner_missed += missed;
        if (missed) CHECK_FALSE(cert);
    }
    CHECK(certified > 30);
    CHECK(corner_missed > 30);
}
