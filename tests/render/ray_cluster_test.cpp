// SPDX-License-Identifier: MIT
// Proposition 11: a cluster declared to miss a triangle never has a ray that hits it.
#include <seamless/render/ray_cluster.h>

#include <catch2/catch.hpp>

#include <random>

using namespace seamless;

namespace {

// Does the segment O + q D, q in [q0, q1], meet the triangle? (Moller-Trumbore in doubles.)
bool segment_hits(Vec3 O, Vec3 D, double q0, double q1, Vec3 a, Vec3 b, Vec3 c) {
    const Vec3 e1 = b - a, e2 = c - a, p = cross(D, e2);
    const double det = dot(e1, p);
    if (std::abs(det) < 1e-14) return false;
    const Vec3 s = O - a;
    const double u = dot(s, p) / det;
    const Vec3 qv = cross(s, e1);
    const double v = dot(D, qv) / det, t = dot(e2, qv) / det;
    return u >= 0 && v >= 0 && u + v <= 1 && t >= q0 && t <= q1;
}

} // namespace

TEST_CASE("Clusters declared to miss a triangle have no ray that hits it", "[ray_cluster]") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(-1, 1), W(0.0, 0.2);
    int misses = 0, hits_seen = 0;
    for (int n = 0; n < 2000; ++n) {
        const Vec3 a{U(rng), U(rng), U(rng)}, b{U(rng), U(rng), U(rng)}, c{U(rng), U(rng), U(rng)};
        const Vec3 O{U(rng) * 2, U(rng) * 2, 2 + U(rng)};
        const Vec3 target{U(rng), U(rng), U(rng)};
        const Vec3 D = target - O;
        const double wo = W(rng), wd = W(rng);
        RayCluster cl;
        for (int i = 0; i < 3; ++i) {
            cl.origin[i] = Interval(O[i] - wo, O[i] + wo);
            cl.direction[i] = Interval(D[i] - wd, D[i] + wd);
        }
        cl.q = Interval(0.0, 1.5);
        const bool may = may_hit_triangle(cl, a, b, c);
        misses += !may;
        // Sample rays of the cluster.
        bool any = false;
        for (int k = 0; k < 200 && !any; ++k) {
            Vec3 o, d;
            for (int i = 0; i < 3; ++i) {
                std::uniform_real_distribution<double> po(cl.origin[i].lo(), cl.origin[i].hi());
                std::uniform_real_distribution<double> pd(cl.direction[i].lo(),
                                                          cl.direction[i].hi());
                o[i] = po(rng);
                d[i] = pd(rng);
            }
            any = segment_hits(o, d, 0.0, 1.5, a, b, c);
        }
        hits_seen += any;
        if (any) CHECK(may);
    }
    // The test exercises both outcomes.
    CHECK(misses > 100);
    CHECK(hits_seen > 100);
}

TEST_CASE("A thin cluster is decided exactly away from the triangle's edges", "[ray_cluster]") {
    RayCluster cl;
    for (int i = 0; i < 3; ++i) cl.origin[i] = Interval(i == 2 ? 5.0 : 0.2);
    cl.direction[0] = Interval(0.0);
    cl.direction[1] = Interval(0.0);
    cl.direction[2] = Interval(-1.0);
    cl.q = Interval(0.0, 10.0);
    CHECK(may_hit_triangle(cl, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
    cl.origin[0] = Interval(0.8);
    cl.origin[1] = Interval(0.8);
    CHECK_FALSE(may_hit_triangle(cl, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
    cl.q = Interval(0.0, 4.0); // stops short of the plane
    cl.origin[0] = Interval(0.2);
    cl.origin[1] = Interval(0.2);
    CHECK_FALSE(may_hit_triangle(cl, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
}

TEST_CASE("ClusterHull rejects only boxes that no ray of the cluster enters", "[ray_cluster]") {
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> U(-1, 1), W(0.0, 0.1);
    int rejected = 0;
    for (int n = 0; n < 3000; ++n) {
        RayCluster cl;
        for (int i = 0; i < 3; ++i) {
            const double o = 3 * U(rng), d = U(rng), wo = W(rng), wd = W(rng);
            cl.origin[i] = Interval(o - wo, o + wo);
            cl.direction[i] = Interval(d - wd, d + wd);
        }
        cl.q = Interval(0.0, 4.0);
        const ClusterHull hull(cl);
        Box3 b;
        const Vec3 c{U(rng) * 2, U(rng) * 2, U(rng) * 2};
        const double h = 0.05 + W(rng) * 3;
        b.extend(c - Vec3{h, h, h});
        b.extend(c + Vec3{h, h, h});
        if (hull.may_meet(b)) continue;
        ++rejected;
        // No sampled point of any ray of the cluster lies in a rejected box.
        for (int k = 0; k < 300; ++k) {
            Vec3 p;
            std::uniform_real_distribution<double> Q(0.0, 4.0);
            const double q = Q(rng);
            for (int i = 0; i < 3; ++i) {
                std::uniform_real_distribution<double> po(cl.origin[i].lo(), cl.origin[i].hi());
                std::uniform_real_distribution<double> pd(cl.direction[i].lo(),
                                                          cl.direction[i].hi());
                p[i] = po(rng) + q * pd(rng);
            }
            CHECK_FALSE(b.contains(p));
        }
    }
    CHECK(rejected > 500);
}

TEST_CASE("A covered cluster has every ray meeting the triangle", "[ray_cluster]") {
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> U(-1, 1), W(0.0, 0.02);
    int covered = 0;
    for (int n = 0; n < 2000; ++n) {
        const Vec3 a{-1 + U(rng) * 0.2, -1 + U(rng) * 0.2, U(rng) * 0.1},
            b{1 + U(rng) * 0.2, -1 + U(rng) * 0.2, U(rng) * 0.1},
            c{U(rng) * 0.2, 1 + U(rng) * 0.2, U(rng) * 0.1};
        RayCluster cl;
        const Vec3 O{U(rng) * 0.5, U(rng) * 0.5, 3};
        const Vec3 target{U(rng) * 0.6, U(rng) * 0.6, -1};
        for (int i = 0; i < 3; ++i) {
            const double wo = W(rng), wd = W(rng);
            cl.origin[i] = Interval(O[i] - wo, O[i] + wo);
            cl.direction[i] = Interval(target[i] - O[i] - wd, target[i] - O[i] + wd);
        }
        cl.q = Interval(0.0, 1.0);
        Interval q;
        if (!covers_triangle(cl, a, b, c, q)) continue;
        ++covered;
        CHECK(may_hit_triangle(cl, a, b, c));
        for (int k = 0; k < 50; ++k) {
            Vec3 o, d;
            for (int i = 0; i < 3; ++i) {
                std::uniform_real_distribution<double> po(cl.origin[i].lo(), cl.origin[i].hi());
                std::uniform_real_distribution<double> pd(cl.direction[i].lo(),
                                                          cl.direction[i].hi());
                o[i] = po(rng);
                d[i] = pd(rng);
            }
            CHECK(segment_hits(o, d, q.lo() - 1e-12, q.hi() + 1e-12, a, b, c));
        }
    }
    CHECK(covered > 200);
}

TEST_CASE("A light's pyramid declared to miss a triangle has no segment that hits it",
          "[ray_cluster]") {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> U(-1, 1), W(0.0, 0.3);
    int misses = 0, hits_seen = 0, tighter = 0;
    for (int n = 0; n < 3000; ++n) {
        const Vec3 a{U(rng), U(rng), U(rng)}, b{U(rng), U(rng), U(rng)}, c{U(rng), U(rng), U(rng)};
        const Vec3 L{U(rng) * 2, U(rng) * 2, 2 + U(rng)};
        const Vec3 mid{U(rng), U(rng), U(rng) - 1};
        IVec<3> ends;
        for (int i = 0; i < 3; ++i) {
            const double w = W(rng);
            ends[i] = Interval(mid[i] - w, mid[i] + w);
        }
        const bool may = pyramid_may_meet_triangle(L, ends, a, b, c);
        misses += !may;
        RayCluster cl;
        for (int i = 0; i < 3; ++i) {
            cl.origin[i] = Interval(L[i]);
            cl.direction[i] = ends[i] - Interval(L[i]);
        }
        tighter += !may && may_hit_triangle(cl, a, b, c);
        bool any = false;
        for (int k = 0; k < 300 && !any; ++k) {
            Vec3 e;
            for (int i = 0; i < 3; ++i) {
                std::uniform_real_distribution<double> pe(ends[i].lo(), ends[i].hi());
                e[i] = pe(rng);
            }
            any = segment_hits(L, e - L, 0.0, 1.0, a, b, c);
        }
        hits_seen += any;
        if (any) CHECK(may);
    }
    CHECK(misses > 300);
    CHECK(hits_seen > 300);
    CHECK(tighter > 0); // it decides clusters that Proposition 11's test leaves open
}
