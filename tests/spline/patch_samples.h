// SPDX-License-Identifier: MIT
// Shared by the power form, enclosure and ray tests: random Bezier patches and
// a long double reference evaluation of a patch and its derivatives.
#pragma once

#include <seamless/spline/bezier_patch.h>

#include <array>
#include <random>

namespace seamless::test {

// Random patch of degree (p, q); control points in [-1,1]^3, weights in [0.3, 3] if rational.
inline BezierPatch random_patch(std::mt19937_64& rng, int p, int q, bool rational) {
    std::uniform_real_distribution<double> P(-1.0, 1.0), W(0.3, 3.0);
    BezierPatch b;
    b.p = p;
    b.q = q;
    b.rational = rational;
    for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j)
            b.at(i, j) = HPoint::from({P(rng), P(rng), P(rng)}, rational ? W(rng) : 1.0);
    return b;
}

struct RefPoint {
    std::array<long double, 3> point, ds, dt, normal;
};

namespace detail {
inline void bernstein_ld(int n, long double s, long double* B, long double* dB) {
    long double tmp[BezierPatch::kMaxOrder] = {1.0L};
    for (int d = 1; d < n; ++d) {
        long double prev = 0;
        for (int i = 0; i < d; ++i) {
            long double t = tmp[i];
            tmp[i] = prev + (1 - s) * t;
            prev = s * t;
        }
        tmp[d] = prev;
    }
    if (n == 0) {
        B[0] = 1;
        dB[0] = 0;
        return;
    }
    for (int i = 0; i <= n; ++i) {
        long double a = i >= 1 ? tmp[i - 1] : 0, c = i <= n - 1 ? tmp[i] : 0;
        B[i] = s * a + (1 - s) * c;
        dB[i] = n * (a - c);
    }
}
} // namespace detail

// Reference values in long double (about 11 more bits than double).
inline RefPoint reference(const BezierPatch& b, double s, double t) {
    long double Bu[BezierPatch::kMaxOrder], dBu[BezierPatch::kMaxOrder];
    long double Bv[BezierPatch::kMaxOrder], dBv[BezierPatch::kMaxOrder];
    detail::bernstein_ld(b.p, s, Bu, dBu);
    detail::bernstein_ld(b.q, t, Bv, dBv);
    long double X[4] = {}, Xs[4] = {}, Xt[4] = {};
    for (int i = 0; i <= b.p; ++i)
        for (int j = 0; j <= b.q; ++j)
            for (int c = 0; c < 4; ++c) {
                long double v = b.at(i, j)[c];
                X[c] += Bu[i] * Bv[j] * v;
                Xs[c] += dBu[i] * Bv[j] * v;
                Xt[c] += Bu[i] * dBv[j] * v;
            }
    RefPoint r;
    for (int c = 0; c < 3; ++c) {
        r.point[c] = X[c] / X[3];
        r.ds[c] = (Xs[c] - r.point[c] * Xs[3]) / X[3];
        r.dt[c] = (Xt[c] - r.point[c] * Xt[3]) / X[3];
    }
    for (int c = 0; c < 3; ++c) {
        int a = (c + 1) % 3, d = (c + 2) % 3;
        r.normal[c] = r.ds[a] * r.dt[d] - r.ds[d] * r.dt[a];
    }
    return r;
}

} // namespace seamless::test
