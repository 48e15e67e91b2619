// SPDX-License-Identifier: MIT
#include <seamless/interval/interval.h>
#include <seamless/tessellate/trimmed/bounds/beyond_side.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless {
namespace {

constexpr double kU = std::numeric_limits<double>::epsilon() / 2; // unit roundoff
constexpr double kInf = std::numeric_limits<double>::infinity();

// Bounds of |S_ss|, |S_st|, |S_tt| over b's local [0,1]^2: the Bernstein
// coefficients of X and W and of their partial derivatives (differences of
// the net, in interval arithmetic) enclose them over the square, and the
// quotient rule runs on those enclosures.
std::array<double, 3> second_derivative_ranges(const BezierPatch& b) {
    const int p = b.p, q = b.q;
    enum { kX, kXs, kXt, kXss, kXst, kXtt, kTerms };
    Interval r[kTerms][4];
    bool seen[kTerms] = {};
    auto add = [&](int term, const Interval(&v)[4]) {
        for (int c = 0; c < 4; ++c) r[term][c] = seen[term] ? hull(r[term][c], v[c]) : v[c];
        seen[term] = true;
    };
    auto X = [&](int i, int j, int c) { return Interval(b.at(i, j)[c]); };
    for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j) {
            Interval v[4];
            for (int c = 0; c < 4; ++c) v[c] = X(i, j, c);
            add(kX, v);
            if (i < p) {
                for (int c = 0; c < 4; ++c) v[c] = double(p) * (X(i + 1, j, c) - X(i, j, c));
                add(kXs, v);
            }
            if (j < q) {
                for (int c = 0; c < 4; ++c) v[c] = double(q) * (X(i, j + 1, c) - X(i, j, c));
                add(kXt, v);
            }
            if (i + 1 < p) {
                for (int c = 0; c < 4; ++c)
                    v[c] =
                        double(p * (p - 1)) * (X(i + 2, j, c) - 2.0 * X(i + 1, j, c) + X(i, j, c));
                add(kXss, v);
            }
            if (i < p && j < q) {
                for (int c = 0; c < 4; ++c)
                    v[c] = double(p * q) *
                           (X(i + 1, j + 1, c) - X(i + 1, j, c) - X(i, j + 1, c) + X(i, j, c));
                add(kXst, v);
            }
            if (j + 1 < q) {
                for (int c = 0; c < 4; ++c)
                    v[c] =
                        double(q * (q - 1)) * (X(i, j + 2, c) - 2.0 * X(i, j + 1, c) + X(i, j, c));
                add(kXtt, v);
            }
        }
    for (int t = 0; t < kTerms; ++t)
        if (!seen[t])
            for (int c = 0; c < 4; ++c) r[t][c] = Interval(0); // degree too low: zero
    const Interval W = r[kX][3], Ws = r[kXs][3], Wt = r[kXt][3];
    const Interval Wss = r[kXss][3], Wst = r[kXst][3], Wtt = r[kXtt][3];
    if (!(W.lo() > 0)) return {kInf, kInf, kInf};
    double ss = 0, st = 0, tt = 0;
    for (int c = 0; c < 3; ++c) {
        const Interval S = r[kX][c] / W;
        const Interval Ss = (r[kXs][c] - S * Ws) / W, St = (r[kXt][c] - S * Wt) / W;
        const Interval Sss = (r[kXss][c] - 2.0 * Ss * Ws - S * Wss) / W;
        const Interval Sst = (r[kXst][c] - Ss * Wt - St * Ws - S * Wst) / W;
        const Interval Stt = (r[kXtt][c] - 2.0 * St * Wt - S * Wtt) / W;
        ss += sqr(Sss).hi(), st += sqr(Sst).hi(), tt += sqr(Stt).hi();
    }
    // The sums of three squares rounded up by a few ulps, then their roots.
    const double up = 1 + 8 * kU;
    return {std::sqrt(ss * up) * up, std::sqrt(st * up) * up, std::sqrt(tt * up) * up};
}

// `b` continued over local s in [s0, s1] (s0 <= 0, s1 >= 1), t alike, by de
// Casteljau's algorithm with steps outside [0,1]; `error` bounds the
// rounding of its homogeneous coordinates (as triangle_restriction.cpp).
BezierPatch continued(const BezierPatch& b, double s0, double s1, double t0, double t1,
                      double& error) {
    BezierPatch cur = b, lo, hi;
    if (s1 > 1) split_u(cur, s1, lo, hi), cur = lo;
    if (s0 < 0) split_u(cur, s0 / std::max(s1, 1.0), lo, hi), cur = hi;
    if (t1 > 1) split_v(cur, t1, lo, hi), cur = lo;
    if (t0 < 0) split_v(cur, t0 / std::max(t1, 1.0), lo, hi), cur = hi;
    double M = 0;
    for (int i = 0; i <= b.p; ++i)
        for (int j = 0; j <= b.q; ++j)
            for (int c = 0; c < 4; ++c) M = std::max(M, std::abs(b.at(i, j)[c]));
    const double g = std::max(1.0, s1 - s0) * std::max(1.0, t1 - t0) * 3;
    error = 6.0 * (b.p + b.q + 2) * kU * M * std::pow(g, b.p + b.q) +
            underflow_allowance(64 * (b.p + b.q));
    return cur;
}

// Bounds A, B, C of P's second derivatives S_uu, S_uv, S_vv over the
// patch continued to local [s0, s1] x [t0, t1] ((u,v) units), or infinite.
std::array<double, 3> continued_curvature(const BezierPatch& patch, double s0, double s1, double t0,
                                          double t1) {
    double error = 0;
    const BezierPatch c = continued(patch, s0, s1, t0, t1, error);
    double wmin = kInf, M = 0;
    for (int i = 0; i <= c.p; ++i)
        for (int j = 0; j <= c.q; ++j) {
            wmin = std::min(wmin, c.at(i, j).w);
            for (int k = 0; k < 3; ++k) M = std::max(M, std::abs(c.at(i, j)[k]));
        }
    if (!(wmin > 2 * error)) return {kInf, kInf, kInf};
    // The rounding of c's net, through second differences and the quotient.
    const double slack =
        16.0 * (c.p + c.q) * (c.p + c.q) * error * (1 + M / (wmin - error)) / (wmin - error);
    const auto d = second_derivative_ranges(c);
    const double wu = (s1 - s0) * (patch.u1 - patch.u0), wv = (t1 - t0) * (patch.v1 - patch.v0);
    return {(d[0] + slack) / (wu * wu), (d[1] + slack) / (wu * wv), (d[2] + slack) / (wv * wv)};
}

// An overhang rounded up to a power of two (0 stays 0).
double rounded_up(double overhang) {
    if (!(overhang > 0)) return 0;
    int e = 0;
    const double m = std::frexp(overhang, &e); // overhang = m 2^e, m in [0.5, 1)
    return std::ldexp(m == 0.5 ? 0.5 : 1.0, e);
}

} // namespace

// Beyond an open side: P's distance to the tangent plane there (header),
// from the second derivatives over the patch continued to the piece (local
// corners st, overhang hu, hv). The pieces along a side reach about as far
// past it: the derivatives are taken over the overhangs rounded up to powers
// of two and kept per thread for the next piece on the same patch with the
// same rounded box (a bound over a larger box holds over a smaller one; the
// box depends on the piece alone, so the bound does not depend on which
// pieces came before).
double beyond_side(const BezierPatch& patch, const std::array<std::array<double, 2>, 3>& st,
                   double hu, double hv) {
    double s0 = 0, s1 = 1, t0 = 0, t1 = 1;
    for (const auto& x : st)
        s0 = std::min(s0, x[0]), s1 = std::max(s1, x[0]), t0 = std::min(t0, x[1]),
        t1 = std::max(t1, x[1]);
    s0 = -rounded_up(-s0), s1 = 1 + rounded_up(s1 - 1);
    t0 = -rounded_up(-t0), t1 = 1 + rounded_up(t1 - 1);
    struct Kept {
        BezierPatch patch;
        double s0 = 0, s1 = 0, t0 = 0, t1 = 0;
        std::array<double, 3> d{};
        bool valid = false;
    };
    static thread_local Kept kept;
    const bool same = kept.valid && kept.s0 == s0 && kept.s1 == s1 && kept.t0 == t0 &&
                      kept.t1 == t1 && kept.patch.p == patch.p && kept.patch.q == patch.q &&
                      kept.patch.u0 == patch.u0 && kept.patch.u1 == patch.u1 &&
                      kept.patch.v0 == patch.v0 && kept.patch.v1 == patch.v1 &&
                      std::equal(patch.cp.begin(), patch.cp.end(), kept.patch.cp.begin(),
                                 [](const HPoint& a, const HPoint& b) {
                                     return a.x == b.x && a.y == b.y && a.z == b.z && a.w == b.w;
                                 });
    if (!same) {
        kept.patch = patch;
        kept.s0 = s0, kept.s1 = s1, kept.t0 = t0, kept.t1 = t1;
        kept.d = continued_curvature(patch, s0, s1, t0, t1);
        kept.valid = true;
    }
    const auto& [A, B, C] = kept.d;
    if (!(A < kInf && B < kInf && C < kInf)) return kInf;
    return (A * hu * hu + 2 * B * hu * hv + C * hv * hv) / 2 * (1 + 1e-12);
}

} // namespace seamless
