// SPDX-License-Identifier: MIT
// The error bound is a true and tight upper bound on the two-way distance
// between each subpatch and its fan triangles: sampled both ways (surface
// points to the nearest triangle, triangle points to their nearest surface
// point), for polynomial and rational patches, poles and moved corners.
#include "test_util.h"

#include <seamless/model/model.h>
#include <seamless/tessellate/bounds/error_bound.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <thread>
#include <utility>
#include <vector>

using namespace seamless;

namespace {

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5).
Vec3 closest_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const Vec3 bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
    const Vec3 cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    const double denom = 1 / (va + vb + vc);
    return a + (vb * denom) * ab + (vc * denom) * ac;
}

struct Tri {
    Vec3 a, b, c;
};

// Distance from x to the closest point of b over [0,1]^2: the nearest of a
// grid of samples over [s0, s1] x [t0, t1] (a neighbourhood where the closest
// point is), refined by damped Gauss-Newton (a point of the surface, so never
// below the true distance; close to it from a dense start).
double distance_to_patch(const BezierPatch& b, Vec3 x, int grid, double s0 = 0, double s1 = 1,
                         double t0 = 0, double t1 = 1) {
    double best = INFINITY, bs = 0, bt = 0;
    for (int i = 0; i <= grid; ++i)
        for (int j = 0; j <= grid; ++j) {
            const double s = s0 + (s1 - s0) * i / grid, t = t0 + (t1 - t0) * j / grid;
            const double d = distance(evaluate(b, s, t).point, x);
            if (d < best) best = d, bs = s, bt = t;
        }
    for (int it = 0; it < 30; ++it) {
        const SurfacePoint sp = evaluate(b, bs, bt);
        const Vec3 r = x - sp.point;
        const double a11 = dot(sp.du, sp.du), a22 = dot(sp.dv, sp.dv), a12 = dot(sp.du, sp.dv);
        const double det = a11 * a22 - a12 * a12;
        if (!(det > 0)) break;
        const double g1 = dot(sp.du, r), g2 = dot(sp.dv, r);
        double ds = (a22 * g1 - a12 * g2) / det, dt = (a11 * g2 - a12 * g1) / det;
        bool improved = false;
        for (int h = 0; h < 10 && !improved; ++h, ds *= 0.5, dt *= 0.5) {
            const double ns = std::clamp(bs + ds, 0.0, 1.0), nt = std::clamp(bt + dt, 0.0, 1.0);
            const double d = distance(evaluate(b, ns, nt).point, x);
            if (d < best) best = d, bs = ns, bt = nt, improved = true;
        }
        if (!improved) break;
    }
    return best;
}

// Two-way sampled distance between sub (over [0,1]^2) and the triangles.
double sampled_distance(const BezierPatch& sub, const std::vector<Tri>& tris, int grid) {
    double worst = 0;
    for (int i = 0; i <= grid; ++i)
        for (int j = 0; j <= grid; ++j) {
            const Vec3 x = evaluate(sub, double(i) / grid, double(j) / grid).point;
            double d = INFINITY;
            for (const Tri& t : tris)
                d = std::min(d, distance(x, closest_on_triangle(x, t.a, t.b, t.c)));
            worst = std::max(worst, d);
        }
    const int n = grid / 2;
    for (const Tri& t : tris)
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                const double l1 = double(i) / n, l2 = double(j) / n;
                const Vec3 x = t.a + l1 * (t.b - t.a) + l2 * (t.c - t.a);
                worst = std::max(worst, distance_to_patch(sub, x, 24));
            }
    return worst;
}

std::vector<Tri> fan_of(Vec3 centre, const std::array<Vec3, 4>& V) {
    std::vector<Tri> t;
    for (int k = 0; k < 4; ++k) t.push_back({centre, V[k], V[(k + 1) % 4]});
    return t;
}

// Quarter cylinder of radius 1 and height 2: rational degree (2, 1).
Model quarter_cylinder() {
    BSplineSurface s;
    s.name = "quarter_cylinder";
    s.degree_u = 2;
    s.degree_v = 1;
    s.size_u = 3;
    s.size_v = 2;
    s.knots_u = {0, 0, 0, 1, 1, 1};
    s.knots_v = {0, 0, 1, 1};
    s.points = {{1, 0, 0}, {1, 0, 2}, {1, 1, 0}, {1, 1, 2}, {0, 1, 0}, {0, 1, 2}};
    const double w = std::sqrt(0.5);
    s.weights = {1, 1, w, w, 1, 1};
    Model m;
    m.surfaces.push_back(s);
    return m;
}

// The bound's claim, sampled: every point of a subpatch's triangles is within
// the subpatch's bound of its Bezier patch, and every point of a subpatch is
// within the largest bound of its patch of the patch's triangles. Checks
// sampled <= bound on every stride-th subpatch and on each patch's first
// subpatch written as two triangles (Subpatch::diagonal); returns the largest
// sampled / bound and how many of those two-triangle subpatches were checked.
void check_subpatches(const Model& m, const TessellationOptions& opt, int grid, int stride,
                      double& worst_ratio, int* quads_checked = nullptr) {
    const auto patches = bezier_patches(m);
    const Tessellation t = tessellate(m, patches, opt);
    std::vector<std::vector<Tri>> patch_tris(patches.size());
    std::vector<double> patch_bound(patches.size(), 0);
    for (const Subpatch& sp : t.subpatches) {
        REQUIRE(sp.error_bound > 0);
        REQUIRE(sp.error_bound <= t.stats.max_error_bound);
        patch_bound[sp.patch] = std::max(patch_bound[sp.patch], sp.error_bound);
        for (int f = sp.first_triangle; f < sp.first_triangle + sp.triangle_count; ++f) {
            const auto& tr = t.mesh.triangles[f];
            patch_tris[sp.patch].push_back(
                {t.mesh.positions[tr[0]], t.mesh.positions[tr[1]], t.mesh.positions[tr[2]]});
        }
    }
    worst_ratio = 0;
    std::vector<char> quad_seen(patches.size(), 0);
    for (size_t i = 0; i < t.subpatches.size(); ++i) {
        const Subpatch& sp = t.subpatches[i];
        const bool first_quad = sp.diagonal >= 0 && !quad_seen[sp.patch];
        if (i % stride != 0 && !first_quad) continue;
        if (sp.diagonal >= 0) {
            REQUIRE(sp.triangle_count == 2);
            quad_seen[sp.patch] = 1;
            if (quads_checked) ++*quads_checked;
        }
        const BezierPatch& b = patches[sp.patch];
        // Triangles -> patch (the closest point is near the subpatch).
        const double ws = param_of(sp.rect.s1) - param_of(sp.rect.s0);
        const double wt = param_of(sp.rect.t1) - param_of(sp.rect.t0);
        const double ns0 = std::max(0.0, param_of(sp.rect.s0) - ws);
        const double ns1 = std::min(1.0, param_of(sp.rect.s1) + ws);
        const double nt0 = std::max(0.0, param_of(sp.rect.t0) - wt);
        const double nt1 = std::min(1.0, param_of(sp.rect.t1) + wt);
        double to_surface = 0;
        const int n = std::max(2, grid / 2);
        for (int f = sp.first_triangle; f < sp.first_triangle + sp.triangle_count; ++f) {
            const auto& tr = t.mesh.triangles[f];
            const Vec3 a = t.mesh.positions[tr[0]], bb = t.mesh.positions[tr[1]],
                       c = t.mesh.positions[tr[2]];
            for (int u = 0; u <= n; ++u)
                for (int v = 0; u + v <= n; ++v) {
                    const Vec3 x = a + (double(u) / n) * (bb - a) + (double(v) / n) * (c - a);
                    to_surface =
                        std::max(to_surface, distance_to_patch(b, x, 40, ns0, ns1, nt0, nt1));
                }
        }
        // Subpatch -> the patch's triangles.
        double to_mesh = 0;
        const BezierPatch sub = extract_subpatch(b, sp.rect);
        for (int u = 0; u <= grid; ++u)
            for (int v = 0; v <= grid; ++v) {
                const Vec3 x = evaluate(sub, double(u) / grid, double(v) / grid).point;
                double d = INFINITY;
                for (const Tri& tr : patch_tris[sp.patch])
                    d = std::min(d, distance(x, closest_on_triangle(x, tr.a, tr.b, tr.c)));
                to_mesh = std::max(to_mesh, d);
            }
        INFO("subpatch " << i << " triangles->patch " << to_surface << " bound " << sp.error_bound
                         << ", subpatch->triangles " << to_mesh << " patch bound "
                         << patch_bound[sp.patch]);
        CHECK(to_surface <= sp.error_bound);
        CHECK(to_mesh <= patch_bound[sp.patch]);
        worst_ratio =
            std::max({worst_ratio, to_surface / sp.error_bound, to_mesh / patch_bound[sp.patch]});
    }
}

} // namespace

TEST_CASE("the error bound holds by sampling on the teapot, spoon, torus and cylinder",
          "[error_bound][heavy]") {
    for (auto path : {test::model_path("teapot.json"), test::model_path("teaspoon.json"),
                      test::shared_dir() / "models/cad/torus.json"}) {
        const Model m = load_model(path);
        INFO(path.filename().string());
        double r = 0;
        check_subpatches(m, {}, 6, 17, r);
        CHECK(r > 0.25);
        TessellationOptions tol;
        tol.tolerance = 1e-3 * d_max(m);
        int quads = 0;
        check_subpatches(m, tol, 4, 211, r, &quads);
        CHECK(quads > 0);
    }
    double r = 0;
    check_subpatches(quarter_cylinder(), {}, 8, 1, r);
    CHECK(r > 0.5);
}

// A paraboloid-like patch over [0, h]^2 whose parametrisation in x speeds up
// along s (control abscissae 0, h/6, h/2, h): a tangential drift. The graph
// of z = (x^2 + y^2) / 2 is not polynomial in (s, t) of this degree; every
// control point is lifted by the paraboloid at it (a smooth, curved patch).
namespace {
BezierPatch drifting_paraboloid(double h) {
    BezierPatch b;
    b.p = b.q = 3;
    const double xs[4] = {0, h / 6, h / 2, h}, ys[4] = {0, h / 3, 2 * h / 3, h};
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 3; ++j)
            b.at(i, j) = HPoint::from({xs[i], ys[j], 0.5 * (xs[i] * xs[i] + ys[j] * ys[j])}, 1);
    return b;
}
} // namespace

TEST_CASE("fan_bound is tight on a curved patch with a non-uniform parametrisation",
          "[error_bound][heavy]") {
    // (Smaller h: the tangential remainder grows like 1/h against the normal
    // deviation and the bound loosens, as error_bound.h says.)
    for (double h : {0.4, 0.1}) {
        const BezierPatch b = drifting_paraboloid(h);
        const Vec3 centre = evaluate(b, 0.5, 0.5).point;
        const std::array<Vec3, 4> V{b.corner(0), b.corner(1), b.corner(2), b.corner(3)};
        const double bound = fan_bound(b, centre, V);
        const double d = sampled_distance(b, fan_of(centre, V), 24);
        INFO("h " << h << " sampled " << d << " bound " << bound);
        CHECK(d <= bound);
        CHECK(d >= 0.25 * bound);
    }
}

TEST_CASE("fan_bound sees moved corners and an off-surface centre", "[error_bound]") {
    BezierPatch b;
    b.p = b.q = 2;
    for (int i = 0; i <= 2; ++i)
        for (int j = 0; j <= 2; ++j)
            b.at(i, j) = HPoint::from({i * 0.5, j * 0.5, (i == 1 && j == 1) ? 0.2 : 0.0}, 1);
    const Vec3 centre = evaluate(b, 0.5, 0.5).point;
    std::array<Vec3, 4> V{b.corner(0), b.corner(1), b.corner(2), b.corner(3)};
    const double exact = fan_bound(b, centre, V);
    CHECK(sampled_distance(b, fan_of(centre, V), 16) <= exact);
    V[1] += Vec3{0, 0, 0.3};
    const double moved = fan_bound(b, centre, V);
    CHECK(moved >= 0.3);
    CHECK(sampled_distance(b, fan_of(centre, V), 16) <= moved);
    const Vec3 up = centre + Vec3{0, 0, 0.5};
    CHECK(fan_bound(b, up, V) >= 0.5);
    CHECK(sampled_distance(b, fan_of(up, V), 16) <= fan_bound(b, up, V));
}

TEST_CASE("certified_fan_bound counts a side vertex off the straight side", "[error_bound]") {
    BezierPatch b;
    b.p = b.q = 1;
    b.at(0, 0) = HPoint::from({0, 0, 0}, 1);
    b.at(1, 0) = HPoint::from({1, 0, 0}, 1);
    b.at(0, 1) = HPoint::from({0, 1, 0}, 1);
    b.at(1, 1) = HPoint::from({1, 1, 0}, 1);
    const int one = kParamOne, half = kParamOne / 2, quarter = kParamOne / 4;
    const Vec3 centre = evaluate(b, 0.5, 0.5).point;
    std::vector<RingPoint> ring{{0, 0, b.corner(0)},   {half, 0, {0.5, 0, 0}},
                                {one, 0, b.corner(1)}, {one, one, b.corner(2)},
                                {0, one, b.corner(3)}, {0, quarter, {0, 0.25, 0}}};
    const ParamRect all;
    CHECK(certified_fan_bound(b, all, 0, centre, ring, 1) < 1e-12);
    ring[5].position = {0, 0.25, 0.01};
    CHECK(certified_fan_bound(b, all, 0, centre, ring, 1) >= 0.01);
    ring[5].position = {0, 0.25, 0};
    ring[1].position = {0.5, -0.02, 0}; // off the patch's side, in its plane
    CHECK(certified_fan_bound(b, all, 0, centre, ring, 1) >= 0.02);
}

TEST_CASE("certified_fan_bound with a target: still a bound, and at or below the target "
          "wherever the untargeted one is",
          "[error_bound][heavy]") {
    // The drifting paraboloid patch above (tangential drift: the coarse
    // refinements and the feet-free first try are looser than the tightest).
    for (double h : {0.4, 0.1}) {
        const BezierPatch b = drifting_paraboloid(h);
        const Vec3 centre = evaluate(b, 0.5, 0.5).point;
        const std::array<Vec3, 4> V{b.corner(0), b.corner(1), b.corner(2), b.corner(3)};
        const int one = kParamOne;
        const std::vector<RingPoint> ring{
            {0, 0, V[0]}, {one, 0, V[1]}, {one, one, V[2]}, {0, one, V[3]}};
        const ParamRect all;
        const double untargeted = certified_fan_bound(b, all, 0, centre, ring, 1);
        const double sampled = sampled_distance(b, fan_of(centre, V), 24);
        REQUIRE(sampled <= untargeted);
        for (double f : {0.5, 0.99, 1.0, 1.5, 4.0, 100.0}) {
            const double target = f * untargeted;
            const double bound = certified_fan_bound(b, all, 0, centre, ring, 1, target);
            INFO("h " << h << " untargeted " << untargeted << " target " << target << " bound "
                      << bound << " sampled " << sampled);
            CHECK(sampled <= bound);
            if (untargeted <= target) CHECK(bound <= target);
        }
    }
}

TEST_CASE("certified_fan_bound: the same value whatever this thread certified before "
          "(phi's memo of shared vertices and sides)",
          "[error_bound]") {
    const BezierPatch b = drifting_paraboloid(0.4), other = drifting_paraboloid(0.1);
    const int half = kParamOne / 2;
    // The four quarters of b: their rings share the sides through the centre.
    std::vector<ParamRect> rects;
    for (int s0 : {0, half})
        for (int t0 : {0, half}) rects.push_back({s0, s0 + half, t0, t0 + half});
    auto ring_of = [&](const BezierPatch& p, const ParamRect& r) {
        std::vector<RingPoint> ring;
        for (auto [s, t] : {std::pair(r.s0, r.t0), std::pair(r.s1, r.t0), std::pair(r.s1, r.t1),
                            std::pair(r.s0, r.t1)})
            ring.push_back({s, t, evaluate(p, param_of(s), param_of(t)).point});
        return ring;
    };
    auto bound = [&](const BezierPatch& p, const ParamRect& r, double target) {
        const Vec3 centre = evaluate(extract_subpatch(p, r), 0.5, 0.5).point;
        return certified_fan_bound(p, r, 1, centre, ring_of(p, r), 1, target);
    };
    for (double target : {0.0, 1e-3}) {
        // Cold: each fan first in a new thread (an empty memo).
        std::vector<double> cold(rects.size());
        for (size_t i = 0; i < rects.size(); ++i)
            std::thread([&, i] { cold[i] = bound(b, rects[i], target); }).join();
        // Warm, forward and backward, with another patch between.
        for (int pass = 0; pass < 2; ++pass)
            for (size_t j = 0; j < rects.size(); ++j) {
                const size_t i = pass == 0 ? j : rects.size() - 1 - j;
                const double warm = bound(b, rects[i], target);
                INFO("target " << target << " fan " << i << " pass " << pass);
                CHECK(std::memcmp(&warm, &cold[i], sizeof warm) == 0);
                bound(other, rects[i], target);
            }
        CHECK(bound(b, ParamRect{}, target) == bound(b, ParamRect{}, target));
    }
}

TEST_CASE("the rational quarter cylinder: every vertex within the bound of the cylinder",
          "[error_bound]") {
    const Model m = quarter_cylinder();
    const Tessellation t = tessellate(m, {});
    for (const Vec3& p : t.mesh.positions)
        CHECK(std::abs(std::hypot(p.x, p.y) - 1) <= t.stats.max_error_bound);
    CHECK(t.stats.max_error_bound < 0.01);
}
