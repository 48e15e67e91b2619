// SPDX-License-Identifier: MIT
// The lane pairs of interval/lanes.h give bit for bit the bounds of the scalar
// Interval operations, over all magnitudes (subnormal to 2^499), signs and zeros.
#include <seamless/interval/lanes.h>

#include <catch2/catch.hpp>

#include "lanes_random.h"

using namespace seamless;

TEST_CASE("Lane pair operations equal the scalar interval ones bit for bit", "[lanes]") {
    std::mt19937 rng(1234);
    int checked = 0;
    for (int n = 0; n < 200000; ++n) {
        const Interval a = test::random_magnitude_interval(rng, 500);
        const Interval b = test::random_magnitude_interval(rng, 500);
        INFO("a = " << a << ", b = " << b);
        REQUIRE(test::same_bits(lanes::store(lanes::load(a)), a));
        REQUIRE(test::same_bits(lanes::store(lanes::sub(lanes::load(a), lanes::load(b))), a - b));
        REQUIRE(test::same_bits(lanes::store(lanes::mul(lanes::Factor(a), lanes::load(b))), a * b));
        REQUIRE(
            test::same_bits(lanes::store(lanes::hull(lanes::load(a), lanes::load(b))), hull(a, b)));
        REQUIRE(test::same_bits(lanes::store(lanes::hull(lanes::empty(), lanes::load(b))),
                                hull(Interval::empty(), b)));
        ++checked;
    }
    CHECK(checked == 200000);
}

TEST_CASE("Lane weight products equal the scalar interval product bit for bit", "[lanes]") {
    // weight_up takes the larger of w.lo x and w.hi x per lane: for w in [0, 1]
    // that is the sign-selected bound of the interval product w x.
    std::mt19937 rng(4321);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int n = 0; n < 200000; ++n) {
        double w0 = n % 7 == 0 ? 0.0 : unit(rng), w1 = n % 11 == 0 ? 1.0 : unit(rng);
        if (w1 < w0) std::swap(w0, w1);
        if (n % 5 == 0) w1 = w0; // thin weights
        const Interval w(w0, w1);
        const Interval x = test::random_magnitude_interval(rng, 500);
        INFO("w = " << w << ", x = " << x);
        const lanes::Lanes y =
            lanes::weight_up(lanes::splat(w.lo()), lanes::splat(w.hi()), lanes::load(x));
        REQUIRE(test::same_bits(lanes::store(y), w * x));
    }
}

TEST_CASE("Lane quotients by positive intervals equal the scalar ones bit for bit", "[lanes]") {
    std::mt19937 rng(999);
    int checked = 0;
    for (int n = 0; n < 200000; ++n) {
        const Interval x = test::random_magnitude_interval(rng, 500);
        Interval z = test::random_magnitude_interval(rng, 500);
        z = Interval::hull(std::abs(z.lo()), std::abs(z.hi()));
        if (!(z.lo() >= 0x1p-500)) continue; // the lanes' condition
        INFO("x = " << x << ", z = " << z);
        const lanes::Lanes q =
            lanes::quotient_positive(lanes::load(x), lanes::splat(z.lo()), lanes::splat(z.hi()));
        REQUIRE(test::same_bits(lanes::store(q), x / z));
        ++checked;
    }
    CHECK(checked > 50000);
}

TEST_CASE("Lane paths are refused for huge, infinite and NaN bounds", "[lanes]") {
    const Interval c[3] = {Interval(-1.0, 2.0), Interval(0x1p499), Interval(-0x1p-1074, 0.0)};
    CHECK(lanes::moderate(c, 3, 0x1p500));
    for (double bad : {0x1p500, -0x1p600, std::numeric_limits<double>::infinity(),
                       std::numeric_limits<double>::quiet_NaN()}) {
        Interval d[3] = {c[0], c[1], c[2]};
        d[1] = Interval::hull(0.0, bad);
        if (std::isnan(bad)) d[1] = Interval(0.0, bad);
        CHECK_FALSE(lanes::moderate(d, 3, 0x1p500));
    }
    const Interval empty = Interval::empty();
    CHECK_FALSE(lanes::moderate(&empty, 1, 0x1p500));
}
