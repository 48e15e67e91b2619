// SPDX-License-Identifier: MIT
// Subpatches (de Casteljau restriction with interval ends): the hull of the
// restricted coefficients holds every point of the patch over the box, the
// screen enclosure every projected point, and both shrink with the box.
#include <seamless/spline/subpatch.h>

#include <catch2/catch.hpp>

#include "patch_samples.h"

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

TEST_CASE("Restricted subpatches enclose the patch over their box", "[subpatch]") {
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
