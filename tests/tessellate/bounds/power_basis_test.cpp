// SPDX-License-Identifier: MIT
// The power-basis evaluator is within its proven rounding bound of the exact
// surface point (a long double Bernstein sum as reference), on the teapot's
// patches and on a patch far from the origin where the rounding shows; its
// derivatives agree with evaluate(), its point alone with its point.
#include "test_util.h"

#include <seamless/model/model.h>
#include <seamless/tessellate/bounds/power_basis.h>

#include <catch2/catch.hpp>

#include <cfloat>
#include <cmath>
#include <random>

using namespace seamless;

namespace {

// S(s, t) by the Bernstein sum in long double (64-bit significand on x86:
// about 2000 times finer than the double evaluator's rounding).
std::array<long double, 3> reference(const BezierPatch& b, long double s, long double t) {
    auto basis = [](long double x, long double* B) {
        const long double r = 1 - x;
        B[0] = r * r * r, B[1] = 3 * x * r * r, B[2] = 3 * x * x * r, B[3] = x * x * x;
    };
    long double Bs[4], Bt[4];
    basis(s, Bs);
    basis(t, Bt);
    std::array<long double, 3> p{0, 0, 0};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const HPoint& h = b.at(i, j);
            const long double w = Bs[i] * Bt[j];
            p[0] += w * h.x, p[1] += w * h.y, p[2] += w * h.z;
        }
    return p;
}

// Largest |computed - reference| / error over a grid of parameters (0 and 1
// and points in between that are not dyadic); also checks the derivatives.
double worst_ratio(const BezierPatch& b, double& largest_difference) {
    REQUIRE(has_power_basis(b));
    const PowerBasisPatch pb = power_basis(b);
    REQUIRE(pb.error > 0);
    // Without the rounding bound: the same coefficients (the subdivision's estimates).
    const PowerBasisPatch plain = power_basis(b, false);
    CHECK(plain.error == 0);
    double magnitude = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) magnitude = std::max(magnitude, norm(b.point(i, j)));
    // The reference's own rounding: a few ulps of long double per operation.
    const double slack = 64 * LDBL_EPSILON * magnitude;
    double worst = 0;
    constexpr int n = 23;
    for (int a = 0; a <= n; ++a)
        for (int c = 0; c <= n; ++c) {
            const double s = a == n ? 1.0 : a / (n - 0.37), t = c == n ? 1.0 : c / (n - 0.61);
            const SurfacePoint p = evaluate(pb, s, t);
            // The point alone is the same value (the bound relies on it).
            CHECK(evaluate_point(pb, s, t) == p.point);
            CHECK(evaluate_point(plain, s, t) == p.point);
            const std::array<long double, 3> r = reference(b, s, t);
            const long double dx = p.point.x - r[0], dy = p.point.y - r[1], dz = p.point.z - r[2];
            const double d = static_cast<double>(std::sqrt(dx * dx + dy * dy + dz * dz));
            largest_difference = std::max(largest_difference, d);
            worst = std::max(worst, d / (pb.error + slack));
            const SurfacePoint e = evaluate(b, s, t);
            const double scale = 1e-9 * (norm(e.du) + norm(e.dv) + 1e-300);
            CHECK(norm(p.du - e.du) <= scale);
            CHECK(norm(p.dv - e.dv) <= scale);
        }
    return worst;
}

} // namespace

TEST_CASE("the power basis is within its rounding bound of the surface", "[power_basis]") {
    SECTION("teapot patches") {
        double largest = 0, worst = 0;
        for (const BezierPatch& b : bezier_patches(load_model(test::model_path("teapot.json"))))
            worst = std::max(worst, worst_ratio(b, largest));
        INFO("largest difference " << largest << ", largest difference / bound " << worst);
        CHECK(worst <= 1);
    }
    SECTION("far from the origin, where the rounding shows") {
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> unit(-1, 1);
        double largest = 0, worst = 0, error = 0;
        for (int k = 0; k < 20; ++k) {
            BezierPatch b;
            const Vec3 offset{3e5, -7e5, 1e6};
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j)
                    b.at(i, j) = HPoint::from(
                        offset + Vec3{i + 0.3 * unit(rng), j + 0.3 * unit(rng), unit(rng)}, 1);
            worst = std::max(worst, worst_ratio(b, largest));
            error = std::max(error, power_basis(b).error);
        }
        INFO("largest difference " << largest << ", bound " << error);
        CHECK(worst <= 1);
        // The comparison sees the rounding (a bound of 0 would fail it), and
        // the bound stays far below any tolerance at this size.
        CHECK(largest > 0);
        CHECK(error < 1e-8);
    }
}

TEST_CASE("the power basis is only for polynomial bicubic patches", "[power_basis]") {
    BezierPatch b;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) b.at(i, j) = HPoint::from({1.0 * i, 1.0 * j, 0}, 1);
    CHECK(has_power_basis(b));
    BezierPatch r = b;
    r.at(1, 2) = HPoint::from({1, 2, 0}, 0.5);
    r.rational = true;
    CHECK_FALSE(has_power_basis(r));
    BezierPatch q = b;
    q.p = 2;
    CHECK_FALSE(has_power_basis(q));
}
