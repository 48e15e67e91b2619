// SPDX-License-Identifier: MIT
// Subpatches (de Casteljau restriction with interval ends): the hull of the
// restricted coefficients holds every point of the patch over the box, the
// screen enclosure every projected point, and both shrink with the box.
#include <seamless/spline/enclosure/subpatch.h>

#include <catch2/catch.hpp>

#include "spline/patch_samples.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

using namespace seamless;

namespace {

// The local ends of [lo, hi] within [D0, D1], enclosed.
Interval local(double x, double D0, double D1) {
    return intersect((Interval(x) - Interval(D0)) / (Interval(D1) - Interval(D0)),
                     Interval(0.0, 1.0));
}

} // namespace

TEST_CASE("Restricted subpatches enclose the patch over their box", "[subpatch][heavy]") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    int tight = 0, cases = 0;
    for (int n = 0; n < 120; ++n) {
        const int p = 1 + n % 4, q = 1 + (n / 4) % 4;
        const bool rational = n % 3 == 0;
        BezierPatch b = test::random_patch(rng, p, q, rational);
        // In front of the eye, for the screen enclosure.
        for (int i = 0; i <= p; ++i)
            for (int j = 0; j <= q; ++j) b.at(i, j).z += 4 * b.at(i, j).w;
        const SubpatchShape sh = subpatch_shape(b);
        CHECK(sh.dim == (rational ? 4 : 3));
        std::vector<Interval> c(sh.size());
        control_coefficients(b, sh, c.data());
        double s0 = 0, s1 = 1, t0 = 0, t1 = 1;
        // Nested restrictions, each to a random part of the last box.
        for (int level = 0; level < 6; ++level) {
            const double f = level < 3 ? 0.5 : 0.05;
            const double ns0 = s0 + U(rng) * (1 - f) * (s1 - s0), ns1 = ns0 + f * (s1 - s0);
            const double nt0 = t0 + U(rng) * (1 - f) * (t1 - t0), nt1 = nt0 + f * (t1 - t0);
            restrict_subpatch(c.data(), sh, 0, local(ns0, s0, s1), local(ns1, s0, s1));
            restrict_subpatch(c.data(), sh, 1, local(nt0, t0, t1), local(nt1, t0, t1));
            s0 = ns0, s1 = ns1, t0 = nt0, t1 = nt1;
            const IVec<3> H = subpatch_hull(c.data(), sh);
            Interval pa, pb;
            const bool projected = subpatch_projection(c.data(), sh, pa, pb);
            CHECK(projected);
            for (int k = 0; k < 25; ++k) {
                const double s = s0 + (s1 - s0) * (k % 5) / 4.0, t = t0 + (t1 - t0) * (k / 5) / 4.0;
                const test::RefPoint r = test::reference(b, std::min(s, s1), std::min(t, t1));
                for (int d = 0; d < 3; ++d) {
                    const double x = static_cast<double>(r.point[d]);
                    CHECK(H[d].lo() <= x + 1e-15 * std::abs(x));
                    CHECK(H[d].hi() >= x - 1e-15 * std::abs(x));
                }
                const double a = static_cast<double>(r.point[0] / r.point[2]);
                const double bb = static_cast<double>(r.point[1] / r.point[2]);
                CHECK(pa.lo() <= a + 1e-14);
                CHECK(pa.hi() >= a - 1e-14);
                CHECK(pb.lo() <= bb + 1e-14);
                CHECK(pb.hi() >= bb - 1e-14);
            }
            if (level == 5) {
                ++cases;
                // A box 1e-4 of the whole: the hull is near the patch's extent there.
                tight += H[0].width() < 1e-2 && H[1].width() < 1e-2 && H[2].width() < 1e-2;
            }
        }
    }
    CHECK(tight == cases);
}

TEST_CASE("Point enclosures by de Casteljau hold the long double value", "[subpatch]") {
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    for (int n = 0; n < 400; ++n) {
        const int p = n % BezierPatch::kMaxOrder, q = (n / 3) % BezierPatch::kMaxOrder;
        BezierPatch b = test::random_patch(rng, p, q, n % 2 == 0);
        const double scale = n % 5 == 0 ? 1e6 : 1.0;
        for (auto& h : b.cp)
            for (int c = 0; c < 4; ++c) h[c] *= scale;
        const double s = n % 7 == 0 ? 0.0 : U(rng), t = n % 11 == 0 ? 1.0 : U(rng);
        Interval X[4];
        enclose_homogeneous(b, s, t, 4, X);
        long double Bu[BezierPatch::kMaxOrder], dBu[BezierPatch::kMaxOrder];
        long double Bv[BezierPatch::kMaxOrder], dBv[BezierPatch::kMaxOrder];
        test::detail::bernstein_ld(p, s, Bu, dBu);
        test::detail::bernstein_ld(q, t, Bv, dBv);
        for (int c = 0; c < 4; ++c) {
            long double ref = 0, M = 0;
            for (int i = 0; i <= p; ++i)
                for (int j = 0; j <= q; ++j) {
                    ref += Bu[i] * Bv[j] * b.at(i, j)[c];
                    M = std::max(M, std::abs(static_cast<long double>(b.at(i, j)[c])));
                }
            const long double slack = 1e-17L * M; // the long double reference's own error
            CHECK(static_cast<long double>(X[c].lo()) <= ref + slack);
            CHECK(static_cast<long double>(X[c].hi()) >= ref - slack);
            CHECK(static_cast<long double>(X[c].width()) <= 1e-13L * M + 1e-300L);
        }
    }
}

namespace {

// The restriction written plainly with Interval's operators (the general
// product): left part at u1, then the right part at u0 / u1 within it.
void reference_row(Interval* c, int n, Interval u0, Interval u1) {
    const Interval unit(0.0, 1.0);
    u0 = intersect(u0, unit);
    u1 = intersect(u1, unit);
    const bool cut_hi = !(u1.is_thin() && u1.lo() == 1);
    const bool cut_lo = !(u0.is_thin() && u0.lo() == 0);
    if (cut_hi) {
        const Interval v = intersect(Interval(1.0) - u1, unit);
        for (int k = 1; k <= n; ++k)
            for (int i = n; i >= k; --i) c[i] = v * c[i - 1] + u1 * c[i];
    }
    if (!cut_lo) return;
    const Interval r = intersect(cut_hi ? u0 / u1 : u0, unit);
    const Interval v = intersect(Interval(1.0) - r, unit);
    for (int k = 1; k <= n; ++k)
        for (int i = 0; i <= n - k; ++i) c[i] = v * c[i] + r * c[i + 1];
}

} // namespace

// restrict_subpatch runs its passes on negated lower bounds, two lanes at once,
// below 2^1000 and the scalar passes above: both must give exactly what plain
// interval arithmetic gives, at every magnitude, with zeros of both signs,
// subnormals, wide and thin coefficients, in both directions.
TEST_CASE("Restriction equals plain interval de Casteljau bit for bit", "[subpatch][heavy]") {
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> U(0.0, 1.0), M(-1.0, 1.0);
    std::uniform_int_distribution<int> ex(-1074, 1020);
    auto value = [&]() -> double {
        switch (rng() % 8) {
        case 0:
            return 0.0;
        case 1:
            return -0.0;
        case 2:
            return std::ldexp(M(rng), 1010); // above 2^1000: the scalar passes
        default:
            return std::ldexp(M(rng), ex(rng));
        }
    };
    int compared = 0;
    for (int n = 0; n < 3000; ++n) {
        const SubpatchShape sh{1 + n % 4, (n / 4) % 4, 3 + n % 2};
        std::vector<Interval> c(sh.size());
        const bool huge = n % 5 == 0;
        for (Interval& x : c) {
            double a = value(), b = rng() % 3 == 0 ? a : value();
            if (!huge) a = std::ldexp(a, -100), b = std::ldexp(b, -100);
            x = Interval::hull(a, b);
        }
        const double e0 = U(rng), e1 = e0 + U(rng) * (1 - e0);
        Interval u0 = n % 7 == 0 ? Interval(0.0) : Interval(e0, std::nextafter(e0, 2.0));
        Interval u1 = n % 9 == 0 ? Interval(1.0) : Interval(std::nextafter(e1, -1.0), e1);
        if (u1.lo() < u0.hi()) u1 = Interval(u0.hi(), std::max(u0.hi(), u1.hi()));
        const int dir = n % 2;
        std::vector<Interval> want = c;
        if (dir == 0) {
            for (int d = 0; d < sh.dim; ++d)
                for (int j = 0; j <= sh.q; ++j) {
                    Interval row[BezierPatch::kMaxOrder];
                    for (int i = 0; i <= sh.p; ++i) row[i] = want[sh.index(d, i, j)];
                    reference_row(row, sh.p, u0, u1);
                    for (int i = 0; i <= sh.p; ++i) want[sh.index(d, i, j)] = row[i];
                }
        } else {
            for (int d = 0; d < sh.dim; ++d)
                for (int i = 0; i <= sh.p; ++i)
                    reference_row(&want[sh.index(d, i, 0)], sh.q, u0, u1);
        }
        restrict_subpatch(c.data(), sh, dir, u0, u1);
        for (int k = 0; k < sh.size(); ++k) {
            INFO("case " << n << " coefficient " << k << " got " << c[k] << " want " << want[k]);
            REQUIRE(std::bit_cast<std::uint64_t>(c[k].lo()) ==
                    std::bit_cast<std::uint64_t>(want[k].lo()));
            REQUIRE(std::bit_cast<std::uint64_t>(c[k].hi()) ==
                    std::bit_cast<std::uint64_t>(want[k].hi()));
            ++compared;
        }
    }
    CHECK(compared > 50000);
}

TEST_CASE("Subpatch hulls and screen enclosures equal plain interval code bit for bit",
          "[subpatch]") {
    // Lane paths (moderate bounds, weights and depths >= 2^-500) and the
    // scalar fallback (huge bounds, tiny or non-positive weights) against the
    // hull of the interval quotients written out here.
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> M(-1.0, 1.0);
    std::uniform_int_distribution<int> ex(-600, 600);
    int lane_like = 0;
    for (int n = 0; n < 4000; ++n) {
        const SubpatchShape sh{n % 4, (n / 4) % 4, 3 + (n / 16) % 2};
        const bool huge = n % 7 == 0;
        std::vector<Interval> c(sh.size());
        for (Interval& x : c) {
            const double a = std::ldexp(M(rng), huge ? ex(rng) : ex(rng) / 20);
            x = rng() % 4 == 0 ? Interval(a) : Interval::hull(a, a + std::ldexp(M(rng), -20));
        }
        // Positive depths and weights mostly; some tiny or straddling 0.
        for (int d = 2; d < sh.dim; ++d)
            for (int i = 0; i <= sh.p; ++i)
                for (int j = 0; j <= sh.q; ++j) {
                    Interval& x = c[sh.index(d, i, j)];
                    x = Interval(std::abs(x.lo()), std::abs(x.lo()) + std::abs(x.hi() - x.lo()));
                    if (n % 11 == 0 && i == sh.p) x = Interval(0x1p-700, 0x1p-699);
                    if (n % 13 == 0 && j == 0) x = Interval(-0.5, 1.0);
                }
        IVec<3> want = IVec<3>::empty();
        bool positive_w = true;
        for (int i = 0; i <= sh.p; ++i)
            for (int j = 0; j <= sh.q; ++j)
                positive_w = positive_w && (sh.dim == 3 || c[sh.index(3, i, j)].lo() > 0);
        Interval wa = Interval::empty(), wb = Interval::empty();
        bool positive_z = true;
        for (int i = 0; i <= sh.p; ++i)
            for (int j = 0; j <= sh.q; ++j) {
                for (int d = 0; d < 3; ++d) {
                    Interval x = c[sh.index(d, i, j)];
                    if (sh.dim == 4) x = x / c[sh.index(3, i, j)];
                    want[d] = positive_w ? hull(want[d], x) : Interval::entire();
                }
                const Interval z = c[sh.index(2, i, j)];
                positive_z = positive_z && z.lo() > 0;
                wa = hull(wa, c[sh.index(0, i, j)] / z);
                wb = hull(wb, c[sh.index(1, i, j)] / z);
            }
        const IVec<3> got = subpatch_hull(c.data(), sh);
        INFO("case " << n);
        for (int d = 0; d < 3; ++d) {
            REQUIRE(std::bit_cast<std::uint64_t>(got[d].lo()) ==
                    std::bit_cast<std::uint64_t>(want[d].lo()));
            REQUIRE(std::bit_cast<std::uint64_t>(got[d].hi()) ==
                    std::bit_cast<std::uint64_t>(want[d].hi()));
        }
        Interval a, b;
        REQUIRE(subpatch_projection(c.data(), sh, a, b) == positive_z);
        if (!positive_z) continue;
        lane_like += !huge;
        for (const auto& [g, w] : {std::pair{a, wa}, std::pair{b, wb}}) {
            REQUIRE(std::bit_cast<std::uint64_t>(g.lo()) == std::bit_cast<std::uint64_t>(w.lo()));
            REQUIRE(std::bit_cast<std::uint64_t>(g.hi()) == std::bit_cast<std::uint64_t>(w.hi()));
        }
    }
    CHECK(lane_like > 1000);
}

TEST_CASE("A split gives both restrictions bit for bit", "[subpatch][heavy]") {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> U(0.0, 1.0), M(-1.0, 1.0);
    std::uniform_int_distribution<int> ex(-1074, 1020);
    int compared = 0;
    for (int n = 0; n < 3000; ++n) {
        const SubpatchShape sh{1 + n % 4, (n / 4) % 4, 3 + n % 2};
        const bool huge = n % 5 == 0; // above 2^1000 somewhere: the scalar passes
        std::vector<Interval> c(sh.size());
        for (Interval& x : c) {
            const double a = std::ldexp(M(rng), huge ? ex(rng) : ex(rng) / 10);
            x = rng() % 3 == 0 ? Interval(a) : Interval::hull(a, std::ldexp(M(rng), ex(rng) / 10));
        }
        const double e = U(rng);
        Interval u = Interval(e, std::nextafter(e, 2.0));
        if (n % 11 == 0) u = Interval(0.0);
        if (n % 13 == 0) u = Interval(1.0);
        if (n % 17 == 0) u = Interval(e); // thin inside
        const int dir = (n / 2) % 2;
        std::vector<Interval> lo(sh.size()), hi(sh.size()), want_lo = c, want_hi = c;
        split_subpatch(c.data(), sh, dir, u, lo.data(), hi.data());
        restrict_subpatch(want_lo.data(), sh, dir, Interval(0.0), u);
        restrict_subpatch(want_hi.data(), sh, dir, u, Interval(1.0));
        for (int k = 0; k < sh.size(); ++k) {
            INFO("case " << n << " coefficient " << k);
            for (const auto& [g, w] :
                 {std::pair{lo[k], want_lo[k]}, std::pair{hi[k], want_hi[k]}}) {
                REQUIRE(std::bit_cast<std::uint64_t>(g.lo()) ==
                        std::bit_cast<std::uint64_t>(w.lo()));
                REQUIRE(std::bit_cast<std::uint64_t>(g.hi()) ==
                        std::bit_cast<std::uint64_t>(w.hi()));
            }
            ++compared;
        }
    }
    CHECK(compared > 50000);
}
