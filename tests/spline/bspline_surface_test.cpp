// SPDX-License-Identifier: MIT
// B-spline surface evaluation: partition of unity, derivatives against finite
// differences, exact rational geometry.
#include "random_surface.h"
#include "test_util.h"

#include <seamless/model/model.h>
#include <seamless/spline/bspline_surface.h>

#include <catch2/catch.hpp>

using namespace seamless;

TEST_CASE("Basis functions sum to one and derivatives sum to zero", "[bspline]") {
    std::mt19937 rng(5);
    for (int p = 1; p <= 9; ++p) {
        auto U = test::random_knots(rng, p, p + 4, rng() % 2);
        std::uniform_real_distribution<double> T(U[p], U[p + 4]);
        for (int n = 0; n < 100; ++n) {
            double t = T(rng), N0[10], N1[10];
            int k = find_span(p, p + 4, U, t);
            REQUIRE(U[k] <= t);
            REQUIRE(t <= U[k + 1]);
            basis_functions(p, k, U, t, N0, N1);
            double s0 = 0, s1 = 0;
            for (int r = 0; r <= p; ++r) {
                CHECK(N0[r] >= -1e-15);
                s0 += N0[r];
                s1 += N1[r];
            }
            CHECK(s0 == Approx(1.0).epsilon(1e-13));
            CHECK(std::abs(s1) <= 1e-9 * (1 + std::abs(N1[0])));
        }
    }
}

TEST_CASE("Partial derivatives agree with central differences", "[bspline]") {
    std::mt19937 rng(6);
    for (bool rational : {false, true}) {
        BSplineSurface s = test::random_surface(rng, {3, 4, true, rational});
        std::uniform_real_distribution<double> A(0.05, 0.95);
        for (int n = 0; n < 50; ++n) {
            double u = s.u_min() + A(rng) * (s.u_max() - s.u_min());
            double v = s.v_min() + A(rng) * (s.v_max() - s.v_min());
            // Stay inside one knot span so the difference quotient is smooth.
            const double h = 1e-6;
            int ku = find_span(3, s.size_u, s.knots_u, u),
                kv = find_span(4, s.size_v, s.knots_v, v);
            if (u - h < s.knots_u[ku] || u + h > s.knots_u[ku + 1]) continue;
            if (v - h < s.knots_v[kv] || v + h > s.knots_v[kv + 1]) continue;
            SurfacePoint p = evaluate(s, u, v);
            Vec3 du = (evaluate(s, u + h, v).point - evaluate(s, u - h, v).point) / (2 * h);
            Vec3 dv = (evaluate(s, u, v + h).point - evaluate(s, u, v - h).point) / (2 * h);
            CHECK(distance(p.du, du) <= 1e-5 * (1 + norm(du)));
            CHECK(distance(p.dv, dv) <= 1e-5 * (1 + norm(dv)));
        }
    }
}

TEST_CASE("The point alone is the point of the full evaluation, to the bit", "[bspline]") {
    std::mt19937 rng(7);
    for (bool rational : {false, true})
        for (int p : {1, 2, 3, 5}) {
            const BSplineSurface s = test::random_surface(rng, {p, p + 1, true, rational});
            std::uniform_real_distribution<double> A(-0.1, 1.1); // clamped outside
            for (int n = 0; n < 200; ++n) {
                const double u = s.u_min() + A(rng) * (s.u_max() - s.u_min());
                const double v = s.v_min() + A(rng) * (s.v_max() - s.v_min());
                const Vec3 full = evaluate(s, u, v).point, alone = evaluate_point(s, u, v);
                CHECK(full.x == alone.x);
                CHECK(full.y == alone.y);
                CHECK(full.z == alone.z);
            }
        }
}

TEST_CASE("Rational models are exact: quarter cylinder and torus", "[bspline]") {
    const Model cyl = load_model(test::model_path("quarter_cylinder.json"));
    const Model tor = load_model(test::model_path("torus_exact.json"));
    for (int n = 0; n <= 20; ++n)
        for (int m = 0; m <= 20; ++m) {
            double u = n / 20.0, v = m / 20.0;
            Vec3 p = evaluate(cyl.surfaces[0], u, v).point;
            CHECK(std::hypot(p.x, p.y) == Approx(1.0).epsilon(1e-14));
            CHECK(p.z == Approx(2.0 * v).margin(1e-14));
            Vec3 q = evaluate(tor.surfaces[0], u, v).point;
            double rho = std::hypot(q.x, q.y) - 2.0;
            CHECK(std::hypot(rho, q.z) == Approx(0.5).epsilon(1e-13));
        }
}

TEST_CASE("Surface normals of the bundled closed models point outward", "[bspline]") {
    for (const char* name : {"sphere.json", "torus.json", "torus_exact.json"}) {
        INFO(name);
        const Model m = load_model(test::model_path(name));
        for (const BSplineSurface& s : m.surfaces) {
            double u = 0.5 * (s.u_min() + s.u_max()) + 0.01,
                   v = 0.5 * (s.v_min() + s.v_max()) + 0.02;
            SurfacePoint p = evaluate(s, u, v);
            Vec3 outward = p.point;
            if (std::string(name) != "sphere.json") { // away from the tube's core circle
                double a = std::atan2(p.point.y, p.point.x);
                outward = p.point - 2.0 * Vec3{std::cos(a), std::sin(a), 0};
            }
            CHECK(dot(p.normal(), outward) > 0);
        }
    }
}
