// SPDX-License-Identifier: MIT
// Every operation of Interval encloses the exact result. Exactness is decided
// with error-free transformations: for a rounded result r of a op b the exact
// value is r + e with e exactly representable (TwoSum; fma for products,
// quotients and square roots), so "lo <= exact" is "lo < r or (lo == r and e >= 0)".
#include <seamless/interval/interval.h>

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

using seamless::Interval;

namespace {

// Exact value r + e (sign of e is what matters, |e| <= ulp(r) / 2).
struct Exact {
    double r, e;
};
Exact exact_sum(double a, double b) {
    double s = a + b, bb = s - a;
    return {s, (a - (s - bb)) + (b - bb)};
}
Exact exact_prod(double a, double b) {
    double p = a * b;
    return {p, std::fma(a, b, -p)};
}
Exact exact_quot(double a, double b) {
    double q = a / b;
    double rem = std::fma(-q, b, a); // a - q b, exact
    return {q, (rem == 0) ? 0.0 : ((rem > 0) == (b > 0) ? 1.0 : -1.0)};
}
Exact exact_sqrt(double a) {
    double s = std::sqrt(a);
    return {s, -std::fma(s, s, -a)}; // sign of a - s^2 is the sign of sqrt(a) - s
}
bool le(double lo, Exact x) {
    return lo < x.r || (lo == x.r && x.e >= 0);
}
bool ge(double hi, Exact x) {
    return hi > x.r || (hi == x.r && x.e <= 0);
}
bool holds(Interval i, Exact x) {
    return le(i.lo(), x) && ge(i.hi(), x);
}

double random_double(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> m(-1.0, 1.0);
    std::uniform_int_distribution<int> ex(-40, 40);
    return std::ldexp(m(rng), ex(rng));
}
Interval random_interval(std::mt19937_64& rng) {
    double a = random_double(rng), b = random_double(rng);
    if (rng() % 4 == 0) b = a + std::ldexp(a, -30); // narrow ones too
    return Interval::hull(a, b);
}
double random_in(std::mt19937_64& rng, Interval x) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    switch (rng() % 4) {
    case 0:
        return x.lo();
    case 1:
        return x.hi();
    default:
        return std::clamp(x.lo() + u(rng) * (x.hi() - x.lo()), x.lo(), x.hi());
    }
}

} // namespace

TEST_CASE("next_up and next_down step one ulp", "[interval]") {
    std::mt19937_64 rng(1);
    for (int i = 0; i < 10000; ++i) {
        double x = random_double(rng);
        CHECK(seamless::next_up(x) == std::nextafter(x, INFINITY));
        CHECK(seamless::next_down(x) == std::nextafter(x, -INFINITY));
    }
    CHECK(seamless::next_up(0.0) == std::numeric_limits<double>::denorm_min());
    CHECK(seamless::next_up(-0.0) == std::numeric_limits<double>::denorm_min());
    CHECK(seamless::next_down(0.0) == -std::numeric_limits<double>::denorm_min());
    CHECK(seamless::next_up(INFINITY) == INFINITY);
    CHECK(seamless::next_down(-INFINITY) == -INFINITY);
    CHECK(seamless::next_up(-INFINITY) == -std::numeric_limits<double>::max());
    CHECK(std::isnan(seamless::next_up(NAN)));
}

// next_up and next_down work on the bits without branching on the sign: check
// them against the C library at every kind of double (zeros of both signs,
// subnormals, the largest finite values, infinities) and at random bit patterns
// over the whole range.
TEST_CASE("next_up and next_down at every kind of double", "[interval]") {
    constexpr double inf = std::numeric_limits<double>::infinity();
    constexpr double dmin = std::numeric_limits<double>::denorm_min();
    constexpr double nmin = std::numeric_limits<double>::min();
    constexpr double big = std::numeric_limits<double>::max();
    std::vector<double> xs = {0.0,       -0.0, dmin,  -dmin,       2 * dmin,
                              -2 * dmin, nmin, -nmin, nmin - dmin, -(nmin - dmin),
                              big,       -big, 1.0,   -1.0,        -inf};
    std::mt19937_64 rng(11);
    for (int i = 0; i < 100000; ++i) {
        const double x = std::bit_cast<double>(rng());
        if (!std::isnan(x)) xs.push_back(x);
    }
    for (double x : xs) {
        REQUIRE(std::bit_cast<std::uint64_t>(seamless::next_up(x)) ==
                std::bit_cast<std::uint64_t>(x == 0 ? dmin : std::nextafter(x, inf)));
        if (x != -inf)
            REQUIRE(std::bit_cast<std::uint64_t>(seamless::next_down(x)) ==
                    std::bit_cast<std::uint64_t>(x == 0 ? -dmin : std::nextafter(x, -inf)));
    }
    CHECK(seamless::next_up(inf) == inf);
    CHECK(seamless::next_down(-inf) == -inf);
    CHECK(seamless::next_up(-dmin) == 0.0);
}

// Products and quotients over the whole range of magnitudes, subnormals,
// signed zeros and infinite bounds: the sign cases give exactly the hull of the
// four rounded products stepped outward (rounding to nearest is monotone), and
// every sampled product of points lies inside (a zero bound times an infinite
// one once left out the real 0: [-3e-179, 0] x [-inf, -1.7e140] gave a lower
// bound of 5.4e-39), every sampled quotient too.
TEST_CASE("products and quotients enclose sampled values at every magnitude", "[interval]") {
    constexpr double inf = std::numeric_limits<double>::infinity();
    std::mt19937_64 rng(12);
    std::uniform_int_distribution<int> ex(-1074, 1023);
    std::uniform_real_distribution<double> m(-2.0, 2.0);
    auto any_double = [&]() -> double {
        switch (rng() % 16) {
        case 0:
            return 0.0;
        case 1:
            return -0.0;
        case 2:
            return inf;
        case 3:
            return -inf;
        default:
            return std::ldexp(m(rng), ex(rng));
        }
    };
    int finite = 0, infinite = 0;
    for (int i = 0; i < 200000; ++i) {
        const Interval X = Interval::hull(any_double(), any_double());
        const Interval Y = Interval::hull(any_double(), any_double());
        const Interval P = X * Y;
        REQUIRE(!P.is_empty());
        if (X.is_finite() && Y.is_finite()) {
            ++finite;
            const double p[4] = {X.lo() * Y.lo(), X.lo() * Y.hi(), X.hi() * Y.lo(),
                                 X.hi() * Y.hi()};
            const double lo = std::min(std::min(p[0], p[1]), std::min(p[2], p[3]));
            const double hi = std::max(std::max(p[0], p[1]), std::max(p[2], p[3]));
            REQUIRE(P.lo() == seamless::next_down(lo));
            REQUIRE(P.hi() == seamless::next_up(hi));
        } else {
            ++infinite;
        }
        for (int k = 0; k < 4; ++k) {
            const double x = random_in(rng, X), y = random_in(rng, Y);
            if (!std::isfinite(x) || !std::isfinite(y)) continue;
            const Exact e = exact_prod(x, y);
            if (std::isinf(e.r)) { // overflow: the bound on its side is infinite
                REQUIRE((e.r > 0 ? P.hi() : -P.lo()) == inf);
                continue;
            }
            INFO("X " << X << " Y " << Y << " x " << x << " y " << y);
            REQUIRE(holds(P, e));
            // Quotients likewise (inf / inf corners are no value), where both
            // the quotient and its remainder stay normal.
            if (Y.contains(0.0) || y == 0) continue;
            const Interval Q = X / Y;
            const Exact q = exact_quot(x, y);
            if (std::isinf(q.r)) {
                REQUIRE((q.r > 0 ? Q.hi() : -Q.lo()) == inf);
            } else if (q.r == 0 || std::abs(q.r) > 0x1p-900) {
                REQUIRE(holds(Q, q));
            }
        }
    }
    CHECK(finite > 50000);
    CHECK(infinite > 50000);
}

TEST_CASE("arithmetic encloses the exact result at sampled points", "[interval]") {
    std::mt19937_64 rng(2);
    for (int i = 0; i < 20000; ++i) {
        Interval X = random_interval(rng), Y = random_interval(rng);
        double x = random_in(rng, X), y = random_in(rng, Y);
        REQUIRE(holds(X + Y, exact_sum(x, y)));
        REQUIRE(holds(X - Y, exact_sum(x, -y)));
        REQUIRE(holds(X * Y, exact_prod(x, y)));
        REQUIRE(holds(-X, Exact{-x, 0}));
        if (!Y.contains(0.0))
            REQUIRE(holds(X / Y, exact_quot(x, y)));
        else
            REQUIRE((X / Y) == Interval::entire());
        REQUIRE(holds(seamless::sqr(X), exact_prod(x, x)));
        REQUIRE(holds(seamless::abs(X), Exact{std::abs(x), 0}));
        if (x >= 0) REQUIRE(holds(seamless::sqrt(X), exact_sqrt(x)));
        // Hull and intersection are exact set operations.
        REQUIRE(seamless::hull(X, Y).contains(x));
        REQUIRE(seamless::hull(X, Y).contains(y));
        REQUIRE(seamless::intersect(X, Y).contains(x) == Y.contains(x));
    }
}

TEST_CASE("thin operands: the enclosure is at most two ulps wide", "[interval]") {
    std::mt19937_64 rng(3);
    for (int i = 0; i < 10000; ++i) {
        double a = random_double(rng), b = random_double(rng);
        for (Interval r : {Interval(a) + Interval(b), Interval(a) * Interval(b)}) {
            REQUIRE(r.lo() < r.hi());
            REQUIRE(seamless::next_up(seamless::next_up(r.lo())) >= r.hi());
        }
    }
}

TEST_CASE("mid, rad, width, mag, mig", "[interval]") {
    std::mt19937_64 rng(4);
    for (int i = 0; i < 10000; ++i) {
        Interval X = random_interval(rng);
        double m = X.mid(), r = X.rad();
        REQUIRE(X.contains(m));
        REQUIRE((Interval(m) - Interval(r)).lo() <= X.lo());
        REQUIRE(X.hi() <= (Interval(m) + Interval(r)).hi());
        REQUIRE(holds(Interval(0, X.width()), exact_sum(X.hi(), -X.lo())));
        REQUIRE(X.mag() == std::max(std::abs(X.lo()), std::abs(X.hi())));
        REQUIRE(X.mig() <= std::abs(random_in(rng, X)));
    }
    CHECK(Interval::entire().mid() == 0);
    CHECK(Interval(-1, 2).mig() == 0);
    CHECK(Interval(-3, -2).mig() == 2);
}

TEST_CASE("empty, entire and special values", "[interval]") {
    CHECK(Interval::empty().is_empty());
    CHECK(!Interval(1, 1).is_empty());
    CHECK(Interval(1, 1).is_thin());
    CHECK(Interval(0.0) * Interval::entire() == Interval(0.0));
    CHECK((Interval(1, 2) * Interval(0, INFINITY)).hi() == INFINITY);
    CHECK(seamless::sqrt(Interval(-2, -1)).is_empty());
    CHECK(seamless::sqrt(Interval(-1, 4)).lo() == 0);
    CHECK(seamless::sqrt(Interval(-1, 4)).contains(2.0));
    CHECK(seamless::sqr(Interval(-2, 1)).lo() == 0);
    CHECK(seamless::sqr(Interval(-2, 1)).contains(4.0));
    CHECK(seamless::intersect(Interval(0, 1), Interval(2, 3)).is_empty());
    CHECK(Interval(0, 1).contains_in_interior(Interval(0.25, 0.5)));
    CHECK(!Interval(0, 1).contains_in_interior(Interval(0, 0.5)));
    CHECK(Interval(2, 2).contains_in_interior(Interval(2, 2)));
}

// divide_intersect(num, den, x) must contain every q in x with q d = n for some
// n in num, d in den (Definition 5 with the extended division).
TEST_CASE("divide_intersect keeps every solution of q * d = n", "[interval]") {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-4, 4);
    int zero_dens = 0;
    for (int i = 0; i < 20000; ++i) {
        Interval num = Interval::hull(u(rng), u(rng)), den = Interval::hull(u(rng), u(rng));
        if (i % 3 == 0) den = Interval::hull(-std::abs(u(rng)), std::abs(u(rng))); // 0 in den
        Interval x = Interval::hull(u(rng), u(rng));
        if (den.contains(0.0)) ++zero_dens;
        Interval y = seamless::divide_intersect(num, den, x);
        REQUIRE(x.contains(y));
        // Sample d in den, n in num; q = n / d must be kept when it lies in x.
        double d = random_in(rng, den), n = random_in(rng, num);
        if (d == 0) {
            if (n == 0) REQUIRE(y == x);
            continue;
        }
        Exact q = exact_quot(n, d);
        bool in_x = le(x.lo(), q) && ge(x.hi(), q);
        if (in_x) REQUIRE(holds(y, q));
    }
    CHECK(zero_dens > 5000);
}

TEST_CASE("divide_intersect: the extended cases", "[interval]") {
    using seamless::divide_intersect;
    // [1,2] / [-1,1]: q <= -1 or q >= 1.
    Interval y = divide_intersect({1, 2}, {-1, 1}, {-0.5, 3});
    CHECK(y.lo() <= 1.0);
    CHECK(y.lo() > 0.9);
    CHECK(y.hi() == 3);
    CHECK(divide_intersect({1, 2}, {-1, 1}, {-0.5, 0.5}).is_empty()); // gap: no solution
    CHECK(divide_intersect({1, 2}, {0, 1}, {-5, 5}).lo() > 0.9);      // only q >= 1
    CHECK(divide_intersect({-2, -1}, {0, 1}, {-5, 5}).hi() < -0.9);   // only q <= -1
    CHECK(divide_intersect({-1, 1}, {-1, 1}, {-5, 5}) == Interval(-5, 5));
    CHECK(divide_intersect({1, 2}, {0, 0}, {-5, 5}).is_empty());
    CHECK(divide_intersect({2, 4}, {1, 2}, {0, 10}).contains(Interval(1, 4)));
    CHECK(divide_intersect(Interval::empty(), {1, 2}, {0, 1}).is_empty());
}
