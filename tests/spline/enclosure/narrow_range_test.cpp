// SPDX-License-Identifier: MIT
// polynomial_range with coefficients as narrow as rounding leaves them (the
// power forms of a patch, a single ray's system) takes one real range of the
// midpoint polynomial widened by the coefficients' widths instead of Lemma 2's
// two: the result must still contain every polynomial with coefficients in the
// intervals, at every sampled point, and be wider than the midpoint
// polynomial's range only by the coefficients' widths.
#include <seamless/spline/enclosure/enclosure.h>

#include <catch2/catch.hpp>

#include <random>

using namespace seamless;

TEST_CASE("narrow-coefficient ranges contain every polynomial in the coefficient intervals",
          "[enclosure]") {
    std::mt19937_64 rng(101);
    std::uniform_real_distribution<double> g(-1, 1), v(0, 1);
    for (int trial = 0; trial < 3000; ++trial) {
        const int n = trial % 6;
        const double scale = std::ldexp(1.0, static_cast<int>(g(rng) * 20));
        Interval c[6];
        for (int i = 0; i <= n; ++i) {
            const double m = g(rng) * scale;
            // narrow (the path under test), yet far wider than rounding, so
            // that a missing widening would show
            const double w = std::abs(m) * 0x1p-33 * v(rng);
            c[i] = Interval(next_down(m - w), next_up(m + w));
        }
        const double a = v(rng), b = v(rng);
        const Interval u = trial % 5 == 0 ? Interval(a) : Interval::hull(a, b);
        const Interval r = polynomial_range(c, n, u);
        long double lo = std::numeric_limits<long double>::infinity(), hi = -lo;
        for (int k = 0; k <= 16; ++k) {
            const double x = u.lo() + (u.hi() - u.lo()) * k / 16.0;
            // the extreme polynomials at x >= 0: all lower and all upper coefficients
            long double pl = 0, ph = 0;
            for (int i = n; i >= 0; --i) {
                pl = pl * x + c[i].lo();
                ph = ph * x + c[i].hi();
            }
            REQUIRE(r.lo() <= pl);
            REQUIRE(r.hi() >= ph);
            lo = std::min(lo, pl);
            hi = std::max(hi, ph);
        }
        // Tight: no wider than the range of the midpoint polynomial (thin
        // coefficients) by more than the coefficients' widths allow.
        Interval cm[6];
        double wsum = 0;
        for (int i = 0; i <= n; ++i) {
            cm[i] = Interval(c[i].mid());
            wsum += c[i].width();
        }
        const Interval rm = polynomial_range(cm, n, u);
        CHECK(r.width() <= rm.width() + 4 * wsum + 1e-13 * scale);
        CHECK(lo <= hi);
    }
}
