// SPDX-License-Identifier: MIT
// The error bound is a true upper bound: sampled both ways between each planar
// subpatch and its fan triangles, for polynomial and rational patches.
#include "test_util.h"

#include <seamless/model/model.h>
#include <seamless/tessellate/error_bound.h>
#include <seamless/tessellate/tessellation.h>

#include <catch2/catch.hpp>

#include <cmath>

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

// Largest sampled deviation relative to the bound, over every subpatch, both ways.
double worst_ratio(const Model& m, const TessellationOptions& opt, int grid) {
    const auto patches = bezier_patches(m);
    const Tessellation t = tessellate(m, patches, opt);
    const TriangleMesh& mesh = t.mesh;
    double worst = 0;
    for (const Subpatch& sp : t.subpatches) {
        REQUIRE(sp.error_bound > 0);
        REQUIRE(sp.error_bound <= t.stats.max_error_bound);
        const BezierPatch& b = patches[sp.patch];
        // Surface to triangles: distance to the nearest fan triangle.
        for (int i = 0; i <= grid; ++i)
            for (int j = 0; j <= grid; ++j) {
                const double s =
                    param_of(sp.rect.s0) + (param_of(sp.rect.s1) - param_of(sp.rect.s0)) * i / grid;
                const double tt =
                    param_of(sp.rect.t0) + (param_of(sp.rect.t1) - param_of(sp.rect.t0)) * j / grid;
                const Vec3 x = evaluate(b, s, tt).point;
                double d = INFINITY;
                for (int f = sp.first_triangle; f < sp.first_triangle + sp.triangle_count; ++f) {
                    const auto& tr = mesh.triangles[f];
                    d = std::min(d, distance(x, closest_on_triangle(x, mesh.positions[tr[0]],
                                                                    mesh.positions[tr[1]],
                                                                    mesh.positions[tr[2]])));
                }
                worst = std::max(worst, d / sp.error_bound);
            }
        // Triangles to surface: a triangle point against the surface point at the
        // same interpolated (u, v), which bounds the distance from above.
        for (int f = sp.first_triangle; f < sp.first_triangle + sp.triangle_count; ++f) {
            const auto& tr = mesh.triangles[f];
            const auto& uv = mesh.corner_uvs[f];
            for (auto l : {std::array<double, 3>{1. / 3, 1. / 3, 1. / 3},
                           {0.5, 0.5, 0},
                           {0, 0.5, 0.5},
                           {0.5, 0, 0.5},
                           {0.1, 0.8, 0.1},
                           {0.7, 0.15, 0.15}}) {
                Vec3 x{};
                double u = 0, v = 0;
                for (int k = 0; k < 3; ++k) {
                    x += l[k] * mesh.positions[tr[k]];
                    u += l[k] * uv[k][0];
                    v += l[k] * uv[k][1];
                }
                const double s = (u - b.u0) / (b.u1 - b.u0), tt = (v - b.v0) / (b.v1 - b.v0);
                const double d = distance(x, evaluate(b, s, tt).point);
                worst = std::max(worst, d / sp.error_bound);
            }
        }
    }
    return worst;
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

} // namespace

TEST_CASE("the error bound holds by sampling on the teapot, spoon and torus", "[error_bound]") {
    for (auto path : {test::model_path("teapot.json"), test::model_path("teaspoon.json"),
                      test::shared_dir() / "models/cad/torus.json"}) {
        const Model m = load_model(path);
        INFO(path.filename().string());
        CHECK(worst_ratio(m, {}, 6) <= 1.0);
        TessellationOptions fine;
        fine.eps1 = 0.001 * d_max(m) / 30;
        fine.eps2 = 0.02 * d_max(m) / 30;
        CHECK(worst_ratio(m, fine, 3) <= 1.0);
    }
}

TEST_CASE("the error bound holds for a rational patch and is not vacuous", "[error_bound]") {
    const Model m = quarter_cylinder();
    const double r = worst_ratio(m, {}, 8);
    CHECK(r <= 1.0);
    CHECK(r > 0.05); // the bound is within a factor 20 of what sampling finds
    const Tessellation t = tessellate(m, {});
    // Every vertex is within the bound of the exact cylinder x^2 + y^2 = 1.
    for (const Vec3& p : t.mesh.positions)
        CHECK(std::abs(std::hypot(p.x, p.y) - 1) <= t.stats.max_error_bound);
    CHECK(t.stats.max_error_bound < 0.01);
}

TEST_CASE("bilinear_deviation is exact for bilinear data and positive for curved",
          "[error_bound]") {
    BezierPatch b;
    b.p = 3;
    b.q = 2;
    auto f = [](double s, double t) { return Vec3{s, t, 0.5 * s * t}; };
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 2; ++j) b.at(i, j) = HPoint::from(f(i / 3.0, j / 2.0), 1);
    CHECK(bilinear_deviation(b) < 1e-15);
    b.at(1, 1) = HPoint::from(f(1 / 3.0, 0.5) + Vec3{0, 0, 0.3}, 1);
    CHECK(bilinear_deviation(b) == Approx(0.3));
    // The same patch as a rational one with all weights 2: the same surface.
    BezierPatch r = b;
    r.rational = true;
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 2; ++j) r.at(i, j) = HPoint::from(b.point(i, j), 2);
    // At least |S - B| at (1/3, 1/2): 0.3 B_1^3(1/3) B_1^2(1/2).
    CHECK(bilinear_deviation(r) >= 0.3 * (4.0 / 9) * 0.5 - 1e-12);
    CHECK(bilinear_deviation(r) <= 0.3 + 1e-12);
}

TEST_CASE("fan_deviation is zero for a flat parallelogram and sees the centre offset",
          "[error_bound]") {
    const std::array<Vec3, 4> V{Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{3, 1, 0}, Vec3{1, 1, 0}};
    std::vector<FanVertex> ring{
        {0, 0, V[0]}, {0.5, 0, {1, 0, 0}}, {1, 0, V[1]}, {1, 1, V[2]}, {0, 1, V[3]}};
    CHECK(fan_deviation(V, {1.5, 0.5, 0}, ring) < 1e-15);
    CHECK(fan_deviation(V, {1.5, 0.5, 0.25}, ring) == Approx(0.25));
}
