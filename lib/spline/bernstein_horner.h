// SPDX-License-Identifier: MIT
// A Bernstein sum by Horner's rule (the nested form of Schumaker and Volk,
// CAGD 1986): n steps where the Bernstein basis's recurrence takes n^2, for
// points sampled many times on one Bezier segment or patch of high degree
// (span segments, span patches).
#pragma once

#include <seamless/base/vec.h>

namespace seamless {

// The ratio r of Horner's rule at x in [0, 1]: x / (1 - x) up to the
// middle, past it (1 - x) / x with the sum taken from its other end, so
// that r <= 1. Computed once per point of a patch, for all its rows.
struct HornerRatio {
    double r;
    bool reversed;
    explicit HornerRatio(double x) : r(x <= 0.5 ? x / (1 - x) : (1 - x) / x), reversed(x > 0.5) {}
};

// Sum_j binomial(n, j) x^j (1 - x)^(n - j) c_j, for c[j] = binomial(n, j)
// c_j, divided by (1 - x)^n (by x^n past the middle): a polynomial in r, so
// every step's rounding is that of a convex sum. The factor cancels in the
// projection X.xyz / X.w when every sum of a point has it.
inline HPoint bernstein_horner(const HPoint* c, int n, HornerRatio h) {
    HPoint X;
    if (!h.reversed) {
        X = c[n];
        for (int j = n - 1; j >= 0; --j) X = h.r * X + c[j];
    } else {
        X = c[0];
        for (int j = 1; j <= n; ++j) X = h.r * X + c[j];
    }
    return X;
}

// binomial(n, j) for j = 0..n, into b.
inline void binomials(int n, double* b) {
    double c = 1;
    for (int j = 0; j <= n; ++j) {
        b[j] = c;
        c = c * (n - j) / (j + 1);
    }
}

} // namespace seamless
