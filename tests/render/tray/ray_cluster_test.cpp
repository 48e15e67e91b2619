// SPDX-License-Identifier: MIT
// Proposition 11: a cluster declared to miss a triangle never has a ray that hits it.
#include <seamless/render/tray/blocking_surface.h>
#include <seamless/render/tray/ray_cluster.h>

#include <catch2/catch.hpp>

#include <cmath>
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

// Wide clusters at random triangles, and narrow ones at a big triangle.
void mixed_case(std::mt19937& rng, bool wide, Vec3& a, Vec3& b, Vec3& c, RayCluster& cl) {
    std::uniform_real_distribution<double> U(-1, 1), W(0.0, 0.05);
    a = wide ? Vec3{U(rng), U(rng), U(rng)} : Vec3{-1, -1, U(rng) * 0.1};
    b = wide ? Vec3{U(rng), U(rng), U(rng)} : Vec3{1, -1, U(rng) * 0.1};
    c = wide ? Vec3{U(rng), U(rng), U(rng)} : Vec3{0, 1, U(rng) * 0.1};
    const Vec3 O{U(rng), U(rng), 3}, target{U(rng) * 0.6, U(rng) * 0.6, -1};
    for (int i = 0; i < 3; ++i) {
        const double wo = W(rng) * (wide ? 4 : 0.4), wd = W(rng) * (wide ? 4 : 0.4);
        cl.origin[i] = Interval(O[i] - wo, O[i] + wo);
        cl.direction[i] = Interval(target[i] - O[i] - wd, target[i] - O[i] + wd);
    }
    cl.q = Interval(0.0, 1.0);
}

} // namespace

TEST_CASE("Clusters declared to miss a triangle have no ray that hits it", "[ray_cluster][heavy]") {
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

TEST_CASE("ClusterHull rejects only boxes that no ray of the cluster enters",
          "[ray_cluster][heavy]") {
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

TEST_CASE("meet_triangle answers as may_hit_triangle and covers_triangle", "[ray_cluster]") {
    std::mt19937 rng(17);
    int outcome[3] = {0, 0, 0};
    for (int n = 0; n < 3000; ++n) {
        Vec3 a, b, c;
        RayCluster cl;
        mixed_case(rng, n % 2 == 0, a, b, c, cl);
        Interval q, beta, delta, q2, beta2, delta2;
        const TriangleMeeting m = meet_triangle(cl, a, b, c, q, &beta, &delta);
        const bool may = may_hit_triangle(cl, a, b, c);
        const bool covers = may && covers_triangle(cl, a, b, c, q2, &beta2, &delta2);
        ++outcome[static_cast<int>(m)];
        CHECK((m != TriangleMeeting::miss) == may);
        CHECK((m == TriangleMeeting::covers) == covers);
        if (m == TriangleMeeting::covers && covers) {
            CHECK((q.lo() == q2.lo() && q.hi() == q2.hi()));
            CHECK((beta.lo() == beta2.lo() && beta.hi() == beta2.hi()));
            CHECK((delta.lo() == delta2.lo() && delta.hi() == delta2.hi()));
        }
    }
    // Every answer occurs.
    CHECK(outcome[0] > 100);
    CHECK(outcome[1] > 100);
    CHECK(outcome[2] > 100);
}

TEST_CASE("may_cover_triangle refutes only triangles that the cluster does not cover",
          "[ray_cluster]") {
    std::mt19937 rng(19);
    int covered = 0, refuted = 0, middle_misses = 0;
    for (int n = 0; n < 4000; ++n) {
        Vec3 a, b, c;
        RayCluster cl;
        mixed_case(rng, n % 2 == 0, a, b, c, cl);
        const bool may = may_cover_triangle(cl, a, b, c);
        Interval q;
        if (covers_triangle(cl, a, b, c, q)) {
            ++covered;
            CHECK(may);
        }
        refuted += !may;
        // The middle ray, in doubles: where it clearly misses the triangle's
        // plane region (any q), the interval test refutes.
        const Vec3 om{cl.origin[0].mid(), cl.origin[1].mid(), cl.origin[2].mid()},
            dm{cl.direction[0].mid(), cl.direction[1].mid(), cl.direction[2].mid()};
        const Vec3 e1 = b - a, e2 = c - a, p = cross(dm, e2);
        const double det = dot(e1, p);
        if (std::abs(det) < 1e-3) continue;
        const double u = dot(om - a, p) / det, v = dot(dm, cross(om - a, e1)) / det;
        if (u < -1e-6 || v < -1e-6 || u + v > 1 + 1e-6) {
            ++middle_misses;
            CHECK(!may);
        }
    }
    CHECK(covered > 100);
    CHECK(refuted > 1000);
    CHECK(middle_misses > 1000);
}

TEST_CASE("A light's pyramid declared to miss a triangle has no segment that hits it",
          "[ray_cluster][heavy]") {
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

namespace {

// A wavy height field over [-1, 1]^2 at z about 1, n x n squares, two
// triangles each, counter-clockwise seen from above; `hole`: one triangle left
// out near the middle.
struct Sheet {
    std::vector<Vec3> positions;
    std::vector<std::array<int, 3>> triangles;
};
Sheet wavy_sheet(int n, bool hole) {
    Sheet s;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const double x = -1 + 2.0 * i / n, y = -1 + 2.0 * j / n;
            s.positions.push_back({x, y, 1 + 0.15 * std::sin(3 * x) * std::cos(2 * y)});
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            s.triangles.push_back({a, b, d});
            if (!(hole && i == n / 2 && j == n / 2)) s.triangles.push_back({a, d, c});
        }
    return s;
}

} // namespace

TEST_CASE("Mesh neighbours: across inner edges, none on the border or a flipped triangle",
          "[ray_cluster]") {
    Sheet s = wavy_sheet(3, false);
    std::vector<int> nb = triangle_neighbours(s.triangles);
    int inner = 0;
    for (size_t t = 0; t < s.triangles.size(); ++t)
        for (int e = 0; e < 3; ++e) {
            const int o = nb[3 * t + e];
            if (o < 0) continue;
            ++inner;
            // o traverses the edge the other way round
            const int u = s.triangles[t][e], v = s.triangles[t][(e + 1) % 3];
            bool found = false;
            for (int f = 0; f < 3; ++f)
                found |= s.triangles[o][f] == v && s.triangles[o][(f + 1) % 3] == u;
            CHECK(found);
        }
    CHECK(inner == 2 * (3 * 3 * 3 - 2 * 3));         // 3n^2 - 2n inner edges, seen from both sides
    std::swap(s.triangles[4][0], s.triangles[4][1]); // misoriented against its neighbours
    nb = triangle_neighbours(s.triangles);
    for (int e = 0; e < 3; ++e) CHECK(nb[3 * 4 + e] == -1);
}

TEST_CASE("Mesh neighbours agree with a count of every directed edge on a messy mesh",
          "[ray_cluster]") {
    // Random triangles over few vertices: repeated, reversed and degenerate
    // edges, non-manifold fans, unused vertex numbers.
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> V(0, 11);
    std::vector<std::array<int, 3>> tris(60);
    for (auto& t : tris) t = {V(rng), V(rng), V(rng)};
    const std::vector<int> nb = triangle_neighbours(tris);
    REQUIRE(nb.size() == 3 * tris.size());
    auto traversals = [&](int u, int v, int* last) {
        int c = 0;
        for (size_t f = 0; f < tris.size(); ++f)
            for (int e = 0; e < 3; ++e)
                if (tris[f][e] == u && tris[f][(e + 1) % 3] == v) ++c, *last = static_cast<int>(f);
        return c;
    };
    int paired = 0;
    for (size_t t = 0; t < tris.size(); ++t)
        for (int e = 0; e < 3; ++e) {
            const int u = tris[t][e], v = tris[t][(e + 1) % 3];
            int self = -1, other = -1;
            const bool manifold = traversals(u, v, &self) == 1 && traversals(v, u, &other) == 1;
            CHECK(nb[3 * t + e] == (manifold ? other : -1));
            paired += manifold;
        }
    CHECK(paired > 0);
}

TEST_CASE("A light blocked by a surface of triangles has every segment crossing it",
          "[ray_cluster][heavy]") {
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> U(-1, 1), W(0.0, 0.25);
    int blocked = 0, beyond_one = 0, open = 0;
    for (const bool hole : {false, true}) {
        const Sheet s = wavy_sheet(8, hole);
        const std::vector<int> nb = triangle_neighbours(s.triangles);
        const std::vector<int> group(s.triangles.size(), 0);
        SurfaceScratch scratch;
        auto hits = [&](Vec3 L, Vec3 e, double q_max) {
            for (const auto& t : s.triangles)
                if (segment_hits(L, e - L, 0.0, q_max, s.positions[t[0]], s.positions[t[1]],
                                 s.positions[t[2]]))
                    return true;
            return false;
        };
        for (int n = 0; n < 400; ++n) {
            const Vec3 L{0.5 * U(rng), 0.5 * U(rng), 3 + 0.5 * U(rng)};
            const Vec3 mid{1.2 * U(rng), 1.2 * U(rng), 0.2 * U(rng)};
            IVec<3> ends;
            for (int i = 0; i < 3; ++i) {
                const double w = W(rng) * (i == 2 ? 0.3 : 1);
                ends[i] = Interval(mid[i] - w, mid[i] + w);
            }
            const double q_max = 1 - 1e-9;
            // Seed: the triangle the ray to the box's midpoint meets, if any.
            const Vec3 m{ends[0].mid(), ends[1].mid(), ends[2].mid()};
            int seed = -1;
            for (size_t t = 0; t < s.triangles.size() && seed < 0; ++t) {
                const auto& T = s.triangles[t];
                if (segment_hits(L, m - L, 0.0, 1.0, s.positions[T[0]], s.positions[T[1]],
                                 s.positions[T[2]]))
                    seed = static_cast<int>(t);
            }
            if (seed < 0) continue;
            const BlockerMesh mesh{s.positions, s.triangles, nb, group};
            const bool b =
                pyramid_blocked_by_surface({L, ends, q_max}, seed, mesh, -1, 4096, scratch);
            // The lit surface may not block: the same surface marked `skip` never does.
            CHECK_FALSE(pyramid_blocked_by_surface({L, ends, q_max}, seed, mesh, 0, 4096, scratch));
            bool all = true;
            for (int k = 0; k < 200; ++k) {
                Vec3 e;
                for (int i = 0; i < 3; ++i) {
                    std::uniform_real_distribution<double> pe(ends[i].lo(), ends[i].hi());
                    e[i] = pe(rng);
                }
                all &= hits(L, e, q_max);
            }
            if (b) {
                CHECK(all);
                ++blocked;
                // one triangle alone covering the pyramid?
                RayCluster cl;
                for (int i = 0; i < 3; ++i) {
                    cl.origin[i] = Interval(L[i]);
                    cl.direction[i] = ends[i] - Interval(L[i]);
                }
                bool one = false;
                for (const auto& t : s.triangles) {
                    Interval q;
                    one |= covers_triangle(cl, s.positions[t[0]], s.positions[t[1]],
                                           s.positions[t[2]], q);
                }
                beyond_one += !one;
            }
            open += !all;
        }
    }
    CHECK(blocked > 100);
    CHECK(beyond_one > 50); // pyramids no single triangle covers
    CHECK(open > 20);       // and pyramids reaching past the border or through the hole
}
