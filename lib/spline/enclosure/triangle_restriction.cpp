// SPDX-License-Identifier: MIT
#include <seamless/interval/interval.h>
#include <seamless/spline/enclosure/triangle_restriction.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless {
namespace {

constexpr double kU = std::numeric_limits<double>::epsilon() / 2; // unit roundoff

double binomial(int n, int k) {
    double r = 1;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i; // exact: each partial product is
    return r;                                             // a binomial below 2^53
}

// De Casteljau's algorithm on pts[0..m] with the steps `args` (the blossom
// of the curve at those arguments, into pts[0]).
void blossom(HPoint* pts, int m, const double* args) {
    for (int l = 0; l < m; ++l)
        for (int i = 0; i < m - l; ++i) pts[i] = lerp(pts[i], pts[i + 1], args[l]);
}

// The multiset of `count` arguments: a times x[0], b times x[1], the rest x[2].
int arguments(const double* x, int a, int b, int count, double* args) {
    for (int l = 0; l < count; ++l) args[l] = l < a ? x[0] : l < a + b ? x[1] : x[2];
    return count;
}

} // namespace

// Rounding. Let M bound every homogeneous coordinate of the control points
// and g >= |1 - t| + |t| for every step t (g = 1 inside [0,1]^2). A step
// a + t (b - a) in doubles errs by at most 5.1 g u M_l (u = 2^-53; values of
// level l are below g^l M) and passes earlier errors on with weights of sum g,
// so n levels err by at most 5.1 n g^n u M. The sum over the T terms with
// positive weights of sum 1 (each weight within u of its value) adds
// (T + 2) u g^n M. Gradual underflow: underflow_allowance (interval.h).
void restrict_to_triangle(const BezierPatch& patch, const std::array<std::array<double, 2>, 3>& st,
                          TriangularNet& out) {
    const int p = patch.p, q = patch.q, n = p + q;
    constexpr int K = BezierPatch::kMaxOrder;
    const double s[3] = {st[0][0], st[1][0], st[2][0]}, t[3] = {st[0][1], st[1][1], st[2][1]};
    // U[(a, b)][j]: the u-blossom of column j at s_0^a s_1^b s_2^(p-a-b).
    std::array<HPoint, K*(K + 1) / 2 * K> U;
    auto u_index = [&](int a, int b) { return TriangularNet::index(p, a, b) * (q + 1); };
    HPoint pts[K];
    double args[K];
    for (int a = 0; a <= p; ++a)
        for (int b = 0; a + b <= p; ++b) {
            arguments(s, a, b, p, args);
            for (int j = 0; j <= q; ++j) {
                for (int i = 0; i <= p; ++i) pts[i] = patch.at(i, j);
                blossom(pts, p, args);
                U[u_index(a, b) + j] = pts[0];
            }
        }
    out.n = n;
    std::fill(out.b.begin(), out.b.begin() + TriangularNet::index(n, n, 0) + 1, HPoint{0, 0, 0, 0});
    const double cnp = binomial(n, p);
    int terms = 0;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
            const int k = n - i - j;
            HPoint sum{0, 0, 0, 0};
            int here = 0;
            for (int a = std::max(0, p - j - k); a <= std::min(i, p); ++a)
                for (int b = std::max(0, p - a - k); b <= std::min(j, p - a); ++b) {
                    const int c = p - a - b;
                    // The v-blossom of the u-blossoms at t_0^(i-a) t_1^(j-b) t_2^(k-c).
                    for (int l = 0; l <= q; ++l) pts[l] = U[u_index(a, b) + l];
                    arguments(t, i - a, j - b, q, args);
                    blossom(pts, q, args);
                    const double w = binomial(i, a) * binomial(j, b) * binomial(k, c) / cnp;
                    sum = sum + w * pts[0];
                    ++here;
                }
            out.at(i, j) = sum;
            terms = std::max(terms, here);
        }
    double M = 0;
    for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j)
            for (int c = 0; c < 4; ++c) M = std::max(M, std::abs(patch.at(i, j)[c]));
    double g = 1;
    for (int k = 0; k < 3; ++k)
        g = std::max({g, std::abs(1 - s[k]) + std::abs(s[k]), std::abs(1 - t[k]) + std::abs(t[k])});
    const double grow = std::pow(g, n) * (1 + 1e-10);
    out.error =
        ((5.1 * n + terms + 2) * kU * M * grow + underflow_allowance(16 * n * grow)) * (1 + 1e-10);
}

} // namespace seamless
