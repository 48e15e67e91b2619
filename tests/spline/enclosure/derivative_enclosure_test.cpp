// SPDX-License-Identifier: MIT
// enclose_second and enclose_third (enclosure.h): the second and third partial
// derivatives of the point, enclosed over parameter boxes of random polynomial
// and rational patches, contain the derivatives sampled at points of the box
// (long double reference by differenced control nets and Leibniz's rule).
#include <seamless/spline/enclosure/enclosure.h>

#include "spline/patch_samples.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <random>

using namespace seamless;

namespace {

constexpr int kOrder = 3; // derivatives up to order 3 along each direction

// Bernstein basis of degree n at s (long double), zero above n.
void bernstein(int n, long double s, long double* B) {
    for (int i = 0; i < BezierPatch::kMaxOrder; ++i) B[i] = 0;
    B[0] = 1;
    for (int d = 1; d <= n; ++d)
        for (int i = d; i >= 0; --i) B[i] = (i > 0 ? s * B[i - 1] : 0.0L) + (1 - s) * B[i];
}

// D[k][l][c] = d^(k+l) P_c / ds^k dt^l at (s, t), k + l <= 3, in long double:
// the homogeneous derivatives from the k-fold and l-fold differenced control
// net (times n! / (n - k)!), then P's from X = P W by Leibniz's rule.
using Derivs = std::array<std::array<std::array<long double, 4>, kOrder + 1>, kOrder + 1>;
Derivs reference_derivatives(const BezierPatch& b, double s, double t) {
    Derivs X{}, P{};
    for (int k = 0; k <= kOrder; ++k)
        for (int l = 0; k + l <= kOrder; ++l) {
            if (k > b.p || l > b.q) continue;
            long double net[BezierPatch::kMaxOrder][BezierPatch::kMaxOrder][4];
            for (int i = 0; i <= b.p; ++i)
                for (int j = 0; j <= b.q; ++j)
                    for (int c = 0; c < 4; ++c) net[i][j][c] = b.at(i, j)[c];
            long double scale = 1;
            for (int d = 0; d < k; ++d) {
                scale *= b.p - d;
                for (int i = 0; i < b.p - d; ++i)
                    for (int j = 0; j <= b.q; ++j)
                        for (int c = 0; c < 4; ++c) net[i][j][c] = net[i + 1][j][c] - net[i][j][c];
            }
            for (int d = 0; d < l; ++d) {
                scale *= b.q - d;
                for (int i = 0; i <= b.p - k; ++i)
                    for (int j = 0; j < b.q - d; ++j)
                        for (int c = 0; c < 4; ++c) net[i][j][c] = net[i][j + 1][c] - net[i][j][c];
            }
            long double Bu[BezierPatch::kMaxOrder], Bv[BezierPatch::kMaxOrder];
            bernstein(b.p - k, s, Bu);
            bernstein(b.q - l, t, Bv);
            for (int c = 0; c < 4; ++c) {
                long double v = 0;
                for (int i = 0; i <= b.p - k; ++i)
                    for (int j = 0; j <= b.q - l; ++j) v += Bu[i] * Bv[j] * net[i][j][c];
                X[k][l][c] = scale * v;
            }
        }
    // X^(k,l) = sum_(i<=k, j<=l) C(k,i) C(l,j) P^(i,j) W^(k-i,l-j), solved for P^(k,l).
    const long double C[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
    for (int n = 0; n <= kOrder; ++n)
        for (int k = 0; k <= n; ++k) {
            const int l = n - k;
            for (int c = 0; c < 3; ++c) {
                long double v = X[k][l][c];
                for (int i = 0; i <= k; ++i)
                    for (int j = 0; j <= l; ++j)
                        if (i != k || j != l)
                            v -= C[k][i] * C[l][j] * P[i][j][c] * X[k - i][l - j][3];
                P[k][l][c] = v / X[0][0][3];
            }
        }
    return P;
}

// x holds v up to what the long double reference may be off by (relative to
// the size of the terms it sums, which scale with the control net).
bool holds(Interval x, long double v, long double scale) {
    const long double slack = 1e-15L * (scale + std::fabs(v));
    return x.lo() <= v + slack && x.hi() >= v - slack;
}

} // namespace

TEST_CASE("second and third derivative enclosures contain sampled derivatives",
          "[enclosure][second_order][heavy]") {
    std::mt19937_64 rng(20261202);
    std::uniform_real_distribution<double> u(0, 1);
    long double widest = 0; // not vacuous: the third derivatives are not all zero
    for (const bool rational : {false, true})
        for (int p = 1; p <= 5; ++p)
            for (int q = 1; q <= 5; ++q)
                for (int rep = 0; rep < 3; ++rep) {
                    const BezierPatch b = test::random_patch(rng, p, q, rational);
                    const PatchForms f = patch_forms(b);
                    const double s0 = u(rng), t0 = u(rng), w = 0.5 * u(rng);
                    const ParamBox box{{std::min(s0, 1 - w), std::min(s0, 1 - w) + w},
                                       {std::min(t0, 1 - w), std::min(t0, 1 - w) + w}};
                    const PatchEnclosure e = enclose(f, box);
                    const PatchSecondDerivatives d2 = enclose_second(f, box, e);
                    const PatchThirdDerivatives d3 = enclose_third(f, box, e, d2);
                    // Scale of the reference's rounding: weighted control net
                    // magnitudes times the largest falling factorial (5 * 4 * 3).
                    const long double scale = rational ? 1e4L : 1e2L;
                    for (int n = 0; n < 40; ++n) {
                        const double s = n < 4 ? (n & 1 ? box.s.hi() : box.s.lo())
                                               : box.s.lo() + u(rng) * (box.s.hi() - box.s.lo());
                        const double t = n < 4 ? (n & 2 ? box.t.hi() : box.t.lo())
                                               : box.t.lo() + u(rng) * (box.t.hi() - box.t.lo());
                        const Derivs D = reference_derivatives(b, std::min(s, box.s.hi()),
                                                               std::min(t, box.t.hi()));
                        for (int c = 0; c < 3; ++c) {
                            INFO("p " << p << " q " << q << " rational " << rational << " coord "
                                      << c << " at " << s << ", " << t);
                            REQUIRE(holds(d2.ss[c], D[2][0][c], scale));
                            REQUIRE(holds(d2.st[c], D[1][1][c], scale));
                            REQUIRE(holds(d2.tt[c], D[0][2][c], scale));
                            REQUIRE(holds(d3.sss[c], D[3][0][c], scale));
                            REQUIRE(holds(d3.sst[c], D[2][1][c], scale));
                            REQUIRE(holds(d3.stt[c], D[1][2][c], scale));
                            REQUIRE(holds(d3.ttt[c], D[0][3][c], scale));
                            widest = std::max(widest, std::fabs(D[2][1][c]));
                        }
                    }
                }
    CHECK(widest > 1);
}

TEST_CASE("third derivative enclosures of a polynomial patch are exact on thin boxes",
          "[enclosure][second_order]") {
    // A polynomial patch's third derivatives at a point: Horner on the power
    // form's narrow coefficients, as tight as their rounding.
    std::mt19937_64 rng(7);
    const BezierPatch b = test::random_patch(rng, 3, 3, false);
    const PatchForms f = patch_forms(b);
    const ParamBox box{Interval(0.375), Interval(0.625)};
    const PatchEnclosure e = enclose(f, box);
    const PatchThirdDerivatives d3 = enclose_third(f, box, e, enclose_second(f, box, e));
    const Derivs D = reference_derivatives(b, 0.375, 0.625);
    for (int c = 0; c < 3; ++c) {
        const Interval got[4] = {d3.sss[c], d3.sst[c], d3.stt[c], d3.ttt[c]};
        for (int k = 0; k < 4; ++k) {
            CHECK(holds(got[k], D[3 - k][k][c], 1e2L));
            CHECK(got[k].rad() < 1e-10); // the power form's rounding: about 1e-11
        }
    }
}
