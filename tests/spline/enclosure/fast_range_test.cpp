// SPDX-License-Identifier: MIT
// The fast range enclosures of polynomial_range.cpp (degrees 1 to 3 unrolled, the
// lane forms of lanes.h for moderate coefficients and parameters in [0, 1])
// must give the bits of the generic scalar code (run-time degrees, Interval
// operations) for every degree 0-9, thin, narrow and wide coefficients, boxes
// inside [0,1]^2, thin boxes, and the generic fallbacks (a parameter below 0
// or above 1, huge coefficients); and the enclosures must contain sampled
// values of polynomials with coefficients in the intervals.
#include <seamless/spline/enclosure/enclosure.h>

#include <catch2/catch.hpp>

#include <bit>
#include <cstdint>
#include <random>

using namespace seamless;

namespace {

bool same_bits(Interval a, Interval b) {
    return std::bit_cast<std::uint64_t>(a.lo()) == std::bit_cast<std::uint64_t>(b.lo()) &&
           std::bit_cast<std::uint64_t>(a.hi()) == std::bit_cast<std::uint64_t>(b.hi());
}

// A coefficient of one of four kinds: thin, as narrow as rounding leaves it,
// wide (a cluster system's interval factor), or with a zero or signed-zero bound.
Interval coefficient(std::mt19937_64& rng, int kind, double scale) {
    std::uniform_real_distribution<double> g(-1, 1), v(0, 1);
    const double m = g(rng) * scale;
    switch (kind) {
    case 0:
        return Interval(m);
    case 1:
        return Interval(next_down(next_down(m)), next_up(m));
    case 2:
        return Interval::hull(m, m + g(rng) * scale * v(rng));
    default:
        return v(rng) < 0.5 ? Interval(0.0, std::abs(m)) : Interval(-std::abs(m), -0.0);
    }
}

// A parameter interval: mostly inside [0, 1] (the fast paths), thin, touching
// 0 or 1, and sometimes outside [0, 1] (the generic fallback).
Interval parameter(std::mt19937_64& rng, int trial) {
    std::uniform_real_distribution<double> v(0, 1);
    const double a = v(rng), b = v(rng);
    switch (trial % 8) {
    case 0:
        return Interval(a);
    case 1:
        return Interval(0.0, b);
    case 2:
        return Interval(a, 1.0);
    case 3:
        return Interval(0.0, 1.0);
    case 4:
        return Interval::hull(a - 0.5, b); // lo may be < 0: interval Horner
    case 5:
        return Interval::hull(a, b + 0.5); // hi may be > 1
    default:
        return Interval::hull(a, b);
    }
}

// Sum c_i x^i with each c_i a random point of its interval, in long double.
long double sample(const Interval* c, int n, int stride, long double x, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> v(0, 1);
    long double r = 0;
    for (int i = n; i >= 0; --i) {
        const Interval ci = c[i * stride];
        const long double w = v(rng);
        r = r * x + ((1 - w) * ci.lo() + w * ci.hi());
    }
    return r;
}

} // namespace

TEST_CASE("fast polynomial ranges give the generic code's bits and contain samples",
          "[enclosure][heavy]") {
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> g(-1, 1), v(0, 1);
    for (int trial = 0; trial < 40000; ++trial) {
        const int n = trial % 10;
        const int kind = (trial / 10) % 5; // 4: mixed kinds
        // 2^950: the generic fallback; 2^898: the lane forms' largest coefficients
        const double scale = (trial / 50) % 97 == 0   ? 0x1p950
                             : (trial / 50) % 89 == 0 ? 0x1p898
                                                      : std::ldexp(1.0, int(g(rng) * 30));
        Interval c[PowerForm::kMaxOrder];
        for (int i = 0; i <= n; ++i)
            c[i] = coefficient(rng, kind == 4 ? int(rng() % 4) : kind, scale);
        const Interval u = parameter(rng, trial / 10);
        const Interval r = polynomial_range(c, n, u);
        const Interval ref = polynomial_range_generic(c, n, u);
        INFO("trial " << trial << " n " << n << " u " << u << " r " << r << " ref " << ref);
        REQUIRE(same_bits(r, ref));
        if (scale > 0x1p900) continue; // the fallback; samples are for moderate ones
        for (int k = 0; k < 8; ++k) {
            const long double x = u.lo() + (u.hi() - u.lo()) * static_cast<long double>(v(rng));
            const long double p = sample(c, n, 1, x, rng);
            REQUIRE(r.lo() <= p);
            REQUIRE(p <= r.hi());
        }
    }
}

TEST_CASE("fast horner on power forms gives the generic code's bits and contains samples",
          "[enclosure][heavy]") {
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> g(-1, 1), v(0, 1);
    for (int trial = 0; trial < 6000; ++trial) {
        PowerForm f;
        f.set_degrees(trial % 10, (trial / 10) % 10, 4);
        const int kind = (trial / 100) % 5;
        const double scale = trial % 211 == 0   ? 0x1p950
                             : trial % 199 == 0 ? 0x1p897
                                                : std::ldexp(1.0, int(g(rng) * 20));
        for (int c = 0; c < f.dim; ++c)
            for (int i = 0; i <= f.p; ++i)
                for (int j = 0; j <= f.q; ++j)
                    f.at(c, i, j) = coefficient(rng, kind == 4 ? int(rng() % 4) : kind, scale);
        // boxes inside [0,1]^2: general, thin in s, thin in t, a point, the whole square
        ParamBox box;
        const double a = v(rng), b = v(rng), c0 = v(rng), d = v(rng);
        switch (trial % 5) {
        case 0:
            box = {Interval::hull(a, b), Interval::hull(c0, d)};
            break;
        case 1:
            box = {Interval(a), Interval::hull(c0, d)};
            break;
        case 2:
            box = {Interval::hull(a, b), Interval(c0)};
            break;
        case 3:
            box = {Interval(a), Interval(c0)};
            break;
        default:
            break;
        }
        for (int c = 0; c < f.dim; ++c) {
            const Interval r = horner(f, c, box);
            const Interval ref = horner_generic(f, c, box);
            INFO("trial " << trial << " p " << f.p << " q " << f.q << " c " << c);
            REQUIRE(same_bits(r, ref));
            if (scale > 0x1p900) continue;
            for (int k = 0; k < 4; ++k) {
                const long double s = box.s.lo() + (box.s.hi() - box.s.lo()) * v(rng);
                const long double t = box.t.lo() + (box.t.hi() - box.t.lo()) * v(rng);
                // sum_i (sum_j a_ij t^j) s^i with each a_ij a random point of its interval
                long double val = 0;
                for (int i = f.p; i >= 0; --i)
                    val = val * s + sample(&f.at(c, i, 0), f.q, 1, t, rng);
                REQUIRE(r.lo() <= val);
                REQUIRE(val <= r.hi());
            }
        }
    }
}
