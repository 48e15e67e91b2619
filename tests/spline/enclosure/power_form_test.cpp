// SPDX-License-Identifier: MIT
#include <seamless/spline/enclosure/power_form.h>

#include <seamless/spline/enclosure/enclosure.h>

#include "spline/patch_samples.h"
#include "test_util.h"

#include <seamless/model/model.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <utility>

using namespace seamless;

namespace {

bool same(Interval x, Interval y) {
    return x.lo() == y.lo() && x.hi() == y.hi();
}

// Checks the power form (and its derivatives) of b at random points.
void check_patch(const BezierPatch& b, std::mt19937_64& rng) {
    const PowerForm f = power_form(b), fs = derivative_s(f), ft = derivative_t(f);
    REQUIRE(f.p == b.p);
    REQUIRE(f.q == b.q);
    std::uniform_real_distribution<double> u(0, 1);
    // Rounding allowance: the power basis loses about 2 bits per degree
    // (the coefficients C(n,k) C(k,i) cancel), scaled by the control points.
    double scale = 0, wmin = 1e300;
    for (int i = 0; i <= b.p; ++i)
        for (int j = 0; j <= b.q; ++j) {
            for (int c = 0; c < 4; ++c) scale = std::max(scale, std::abs(b.at(i, j)[c]));
            wmin = std::min(wmin, b.at(i, j).w);
        }
    const double tol = 1e-15 * (std::pow(4.0, b.p + b.q) + 8) * scale / wmin;
    for (int n = 0; n < 200; ++n) {
        double s = n == 0 ? 0 : n == 1 ? 1 : u(rng), t = n == 0 ? 1 : n == 1 ? 0 : u(rng);
        const HPoint h = evaluate_homogeneous(b, s, t);
        const test::RefPoint ref = test::reference(b, s, t);
        for (int c = 0; c < 4; ++c) {
            // Agrees with de Casteljau within rounding.
            const double pm = evaluate_mid(f, c, s, t);
            CHECK(std::abs(pm - h[c]) <= tol);
        }
        for (int c = 0; c < 3; ++c) {
            // The interval power form contains the exact point: X_c = P_c W.
            const Interval Xc = evaluate(f, c, s, t), Wc = evaluate(f, 3, s, t);
            const Interval Pc = Xc / Wc;
            const long double slack = 1e-17L * (1 + std::fabs(ref.point[c]));
            REQUIRE(Pc.lo() <= ref.point[c] + slack);
            REQUIRE(Pc.hi() >= ref.point[c] - slack);
            // Derivative forms: P_s = (X_s - P W_s) / W.
            const Interval Ps = (evaluate(fs, c, s, t) - Pc * evaluate(fs, 3, s, t)) / Wc;
            const Interval Pt = (evaluate(ft, c, s, t) - Pc * evaluate(ft, 3, s, t)) / Wc;
            const long double ss = 1e-16L * (1 + std::fabs(ref.ds[c]));
            const long double st = 1e-16L * (1 + std::fabs(ref.dt[c]));
            REQUIRE(Ps.lo() <= ref.ds[c] + ss);
            REQUIRE(Ps.hi() >= ref.ds[c] - ss);
            REQUIRE(Pt.lo() <= ref.dt[c] + st);
            REQUIRE(Pt.hi() >= ref.dt[c] - st);
            // The enclosure is tight (within the rounding allowance).
            INFO("p " << b.p << " q " << b.q << " width " << Pc.width());
            REQUIRE(Pc.width() < tol);
        }
    }
}

} // namespace

TEST_CASE("power form of random patches agrees with de Casteljau", "[power_form][heavy]") {
    std::mt19937_64 rng(21);
    for (int p = 0; p <= 6; ++p)
        for (int q = 0; q <= 6; ++q)
            for (bool rational : {false, true})
                check_patch(test::random_patch(rng, p, q, rational), rng);
}

TEST_CASE("power form of the teapot patches", "[power_form][heavy]") {
    std::mt19937_64 rng(22);
    const auto patches = bezier_patches(load_model(test::model_path("teapot.json")));
    REQUIRE(patches.size() == 32);
    for (const auto& b : patches) check_patch(b, rng);
}

TEST_CASE("power form of a degree 9 patch", "[power_form]") {
    std::mt19937_64 rng(23);
    check_patch(test::random_patch(rng, 9, 9, false), rng);
    check_patch(test::random_patch(rng, 9, 2, true), rng);
}

TEST_CASE("derivative forms lower the degree; combine is linear", "[power_form]") {
    std::mt19937_64 rng(24);
    const BezierPatch b = test::random_patch(rng, 3, 2, true);
    const PowerForm f = power_form(b);
    CHECK(derivative_s(f).p == 2);
    CHECK(derivative_t(f).q == 1);
    const PowerForm c = derivative_s(power_form(test::random_patch(rng, 0, 2, false)));
    CHECK(c.at(0, 0, 0) == Interval(0.0));
    Interval m[2][PowerForm::kMaxDim] = {{2.0, 0.0, 0.0, -1.0}, {0.0, 1.0, 1.0, 0.0}};
    const PowerForm g = combine(f, m, 2);
    CHECK(g.dim == 2);
    for (double s : {0.0, 0.3, 1.0}) {
        const Interval g0 = evaluate(g, 0, s, 0.7);
        const Interval ref = Interval(2.0) * evaluate(f, 0, s, 0.7) - evaluate(f, 3, s, 0.7);
        CHECK(g0.overlaps(ref));
        CHECK(g0.width() < 1e-10);
    }
}

TEST_CASE("coefficients are packed by the degrees; copies and in-place forms agree",
          "[power_form]") {
    std::mt19937_64 rng(25);
    for (auto [p, q] : {std::pair{3, 3}, {2, 1}, {0, 4}, {9, 9}}) {
        const BezierPatch b = test::random_patch(rng, p, q, true);
        const PowerForm f = power_form(b);
        // A bicubic's 4 x 4 x 4 coefficients are contiguous: (c (p + 1) + i) (q + 1) + j.
        REQUIRE(f.size() == 4 * (p + 1) * (q + 1));
        CHECK(&f.at(3, p, q) - &f.at(0, 0, 0) == f.size() - 1);
        CHECK(&f.at(1, 0, 0) - &f.at(0, 0, 0) == (p + 1) * (q + 1));
        CHECK(&f.at(0, 1, 0) - &f.at(0, 0, 0) == q + 1);
        // In place (into forms holding other degrees) and by value: the same bits.
        PowerForm g = derivative_t(derivative_s(f)), ds = g, dt = g;
        power_form(b, g);
        derivative_s(f, ds);
        derivative_t(f, dt);
        const PowerForm ds_value = derivative_s(f), dt_value = derivative_t(f);
        PowerForm copy;
        copy = f;
        int differ = 0;
        for (int c = 0; c < 4; ++c) {
            for (int i = 0; i <= p; ++i)
                for (int j = 0; j <= q; ++j)
                    differ += !same(g.at(c, i, j), f.at(c, i, j)) +
                              !same(copy.at(c, i, j), f.at(c, i, j));
            for (int i = 0; i <= ds.p; ++i)
                for (int j = 0; j <= ds.q; ++j)
                    differ += !same(ds.at(c, i, j), ds_value.at(c, i, j));
            for (int i = 0; i <= dt.p; ++i)
                for (int j = 0; j <= dt.q; ++j)
                    differ += !same(dt.at(c, i, j), dt_value.at(c, i, j));
        }
        CHECK(differ == 0);
        CHECK((ds.p == std::max(p - 1, 0) && ds.q == q && dt.p == p && dt.q == std::max(q - 1, 0)));
        CHECK((copy.p == p && copy.q == q && copy.dim == 4 && g.p == p && g.q == q));
    }
}

TEST_CASE("forms up to bicubic keep their coefficients inside, and moves keep every bit",
          "[power_form]") {
    // The room inside is a bicubic's (a projected patch's six forms one after
    // another: power_form.h); higher degrees go to the heap.
    STATIC_REQUIRE(sizeof(PowerForm) < 1100);
    STATIC_REQUIRE(sizeof(PatchForms) < 7000);
    std::mt19937_64 rng(31);
    for (auto [p, q] : {std::pair{3, 3}, {2, 2}, {4, 3}, {9, 9}}) {
        const BezierPatch b = test::random_patch(rng, p, q, true);
        const PowerForm f = power_form(b);
        const bool inside = 4 * (p + 1) * (q + 1) <= PowerForm::kInline;
        const auto* object = reinterpret_cast<const char*>(&f);
        const auto* first = reinterpret_cast<const char*>(&f.at(0, 0, 0));
        CHECK((first >= object && first < object + sizeof(PowerForm)) == inside);
        PowerForm moved(std::move(PowerForm(f)));
        PowerForm assigned;
        assigned = std::move(moved);
        // The moved-from form is empty of room it gave away, and usable again.
        moved.set_degrees(9, 9, 4);
        moved.at(3, 9, 9) = Interval(1.0);
        int differ = 0;
        for (int c = 0; c < 4; ++c)
            for (int i = 0; i <= p; ++i)
                for (int j = 0; j <= q; ++j) differ += !same(assigned.at(c, i, j), f.at(c, i, j));
        CHECK(differ == 0);
        CHECK((assigned.p == p && assigned.q == q && assigned.dim == 4));
        CHECK(same(moved.at(3, 9, 9), Interval(1.0)));
    }
}
