// SPDX-License-Identifier: MIT
#include <seamless/spline/enclosure/power_form.h>

#include <seamless/base/check.h>

namespace seamless {
namespace {

// Bernstein-to-power matrix M[k][i] = C(n,k) C(k,i) (-1)^(k-i) for i <= k:
// B_i^n(s) = sum_k M[k][i] s^k. The entries are integers below 2^53: exact.
void bernstein_to_power(int n, double M[][PowerForm::kMaxOrder]) {
    double C[PowerForm::kMaxOrder][PowerForm::kMaxOrder] = {};
    for (int a = 0; a <= n; ++a) {
        C[a][0] = C[a][a] = 1;
        for (int b = 1; b < a; ++b) C[a][b] = C[a - 1][b - 1] + C[a - 1][b];
    }
    for (int k = 0; k <= n; ++k)
        for (int i = 0; i <= n; ++i)
            M[k][i] = i <= k ? C[n][k] * C[k][i] * (((k - i) % 2) ? -1.0 : 1.0) : 0.0;
}

} // namespace

PowerForm power_form(const BezierPatch& b) {
    PowerForm f;
    power_form(b, f);
    return f;
}

void power_form(const BezierPatch& b, PowerForm& f) {
    SEAMLESS_CHECK(b.p >= 0 && b.p <= kMaxDegree && b.q >= 0 && b.q <= kMaxDegree,
                   "a patch of degree at most kMaxDegree");
    constexpr int K = PowerForm::kMaxOrder;
    f.set_degrees(b.p, b.q, 4);
    double Mu[K][K], Mv[K][K];
    bernstein_to_power(b.p, Mu);
    bernstein_to_power(b.q, Mv);
    for (int c = 0; c < 4; ++c) {
        // Rows first: r(i, l) = sum_j Mv[l][j] cp(i, j), then a(k, l) = sum_i Mu[k][i] r(i, l).
        Interval r[K][K];
        for (int i = 0; i <= b.p; ++i)
            for (int l = 0; l <= b.q; ++l) {
                Interval s(0.0);
                for (int j = 0; j <= l; ++j) s += Interval(Mv[l][j]) * Interval(b.at(i, j)[c]);
                r[i][l] = s;
            }
        for (int k = 0; k <= b.p; ++k)
            for (int l = 0; l <= b.q; ++l) {
                Interval s(0.0);
                for (int i = 0; i <= k; ++i) s += Interval(Mu[k][i]) * r[i][l];
                f.at(c, k, l) = s;
            }
    }
}

PowerForm derivative_s(const PowerForm& f) {
    PowerForm d;
    derivative_s(f, d);
    return d;
}

PowerForm derivative_t(const PowerForm& f) {
    PowerForm d;
    derivative_t(f, d);
    return d;
}

void derivative_s(const PowerForm& f, PowerForm& d) {
    // d's degrees are set before f's coefficients are read.
    SEAMLESS_CHECK(&d != &f, "derivative_s into its own argument");
    d.set_degrees(f.p > 0 ? f.p - 1 : 0, f.q, f.dim);
    for (int c = 0; c < f.dim; ++c)
        for (int i = 0; i <= d.p; ++i)
            for (int j = 0; j <= d.q; ++j)
                d.at(c, i, j) =
                    f.p > 0 ? Interval(double(i + 1)) * f.at(c, i + 1, j) : Interval(0.0);
}

void derivative_t(const PowerForm& f, PowerForm& d) {
    SEAMLESS_CHECK(&d != &f, "derivative_t into its own argument");
    d.set_degrees(f.p, f.q > 0 ? f.q - 1 : 0, f.dim);
    for (int c = 0; c < f.dim; ++c)
        for (int i = 0; i <= d.p; ++i)
            for (int j = 0; j <= d.q; ++j)
                d.at(c, i, j) =
                    f.q > 0 ? Interval(double(j + 1)) * f.at(c, i, j + 1) : Interval(0.0);
}

PowerForm combine(const PowerForm& f, const Interval m[][PowerForm::kMaxDim], int rows) {
    PowerForm g;
    combine(f, m, rows, g);
    return g;
}

void combine(const PowerForm& f, const Interval m[][PowerForm::kMaxDim], int rows, PowerForm& g) {
    SEAMLESS_CHECK(rows >= 1 && rows <= PowerForm::kMaxDim && &g != &f,
                   "1 to kMaxDim rows, into another form");
    g.set_degrees(f.p, f.q, rows);
    for (int k = 0; k < rows; ++k)
        for (int i = 0; i <= f.p; ++i)
            for (int j = 0; j <= f.q; ++j) {
                // Exact zeros in m (the primary-ray system's 0 and 1) cost nothing.
                Interval s(0.0);
                for (int c = 0; c < f.dim; ++c)
                    if (!(m[k][c].lo() == 0 && m[k][c].hi() == 0)) s += m[k][c] * f.at(c, i, j);
                g.at(k, i, j) = s;
            }
}

Interval evaluate(const PowerForm& f, int c, double s, double t) {
    const Interval S(s), T(t);
    Interval r(0.0);
    for (int i = f.p; i >= 0; --i) {
        Interval b(0.0);
        for (int j = f.q; j >= 0; --j) b = b * T + f.at(c, i, j);
        r = r * S + b;
    }
    return r;
}

double evaluate_mid(const PowerForm& f, int c, double s, double t) {
    double r = 0;
    for (int i = f.p; i >= 0; --i) {
        double b = 0;
        for (int j = f.q; j >= 0; --j) b = b * t + f.at(c, i, j).mid();
        r = r * s + b;
    }
    return r;
}

} // namespace seamless
