// SPDX-License-Identifier: MIT
#include <seamless/interval/interval.h>
#include <seamless/spline/enclosure/triangle_restriction.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless {
namespace {

constexpr double kU = std::numeric_limits<double>::epsilon() / 2; // unit roundoff

// Binomial coefficients up to the largest total degree (exact doubles).
struct Binomials {
    static constexpr int N = 2 * kMaxDegree + 1;
    std::array<std::array<double, N + 1>, N + 1> c{};
    Binomials() {
        for (int n = 0; n <= N; ++n) {
            c[n][0] = 1;
            for (int k = 1; k <= n; ++k) c[n][k] = c[n - 1][k - 1] + (k < n ? c[n - 1][k] : 0);
        }
    }
};
const Binomials kBinomials;

double binomial(int n, int k) {
    return kBinomials.c[n][k];
}

// Every blossom f(x_0^a x_1^b x_2^c), a + b + c = m, of the curve with
// control points pts[0], pts[stride], ..., pts[m * stride], into
// out[TriangularNet::index(m, a, b)]: de Casteljau's steps shared as a tree
// (the multiset (a, b, c) of level k + 1 from (a - 1, b, c) by a step with
// x_0, else from (a, b - 1, c) with x_1, else from (a, b, c - 1) with x_2).
// Each value still comes from m steps with arguments among x_0, x_1, x_2.
void all_blossoms(const HPoint* pts, int stride, int m, const double* x, HPoint* out) {
    constexpr int K = BezierPatch::kMaxOrder;
    static thread_local std::array<HPoint, K*(K + 1) / 2 * K> level[2];
    for (int i = 0; i <= m; ++i) level[0][i] = pts[i * stride];
    for (int k = 0; k < m; ++k) {
        const auto& from = level[k % 2];
        auto& to = level[(k + 1) % 2];
        const int size = m - k; // points per multiset at level k + 1, plus one
        for (int a = 0; a <= k + 1; ++a)
            for (int b = 0; a + b <= k + 1; ++b) {
                const int parent = a > 0   ? TriangularNet::index(k, a - 1, b)
                                   : b > 0 ? TriangularNet::index(k, a, b - 1)
                                           : TriangularNet::index(k, a, b);
                const double t = a > 0 ? x[0] : b > 0 ? x[1] : x[2];
                const HPoint* src = &from[parent * (size + 1)];
                HPoint* dst = &to[TriangularNet::index(k + 1, a, b) * size];
                for (int i = 0; i < size; ++i) dst[i] = lerp(src[i], src[i + 1], t);
            }
    }
    for (int a = 0; a <= m; ++a)
        for (int b = 0; a + b <= m; ++b)
            out[TriangularNet::index(m, a, b)] = level[m % 2][TriangularNet::index(m, a, b)];
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
    static thread_local std::array<HPoint, K*(K + 1) / 2 * K> U;
    HPoint column[K * (K + 1) / 2], v_blossoms[K * (K + 1) / 2], row[K];
    for (int j = 0; j <= q; ++j) {
        all_blossoms(&patch.at(0, j), K, p, s, column);
        for (int a = 0; a <= p; ++a)
            for (int b = 0; a + b <= p; ++b)
                U[TriangularNet::index(p, a, b) * (q + 1) + j] =
                    column[TriangularNet::index(p, a, b)];
    }
    out.n = n;
    std::fill(out.b.begin(), out.b.begin() + TriangularNet::index(n, n, 0) + 1, HPoint{0, 0, 0, 0});
    // b_ijk gathers the v-blossoms of every u-blossom (a, b, c) at
    // t_0^(i-a) t_1^(j-b) t_2^(k-c) with its weight (header).
    const double cnp = binomial(n, p);
    int terms = 0;
    for (int a = 0; a <= p; ++a)
        for (int b = 0; a + b <= p; ++b) {
            const int c = p - a - b;
            for (int l = 0; l <= q; ++l) row[l] = U[TriangularNet::index(p, a, b) * (q + 1) + l];
            all_blossoms(row, 1, q, t, v_blossoms);
            for (int d = 0; d <= q; ++d)
                for (int e = 0; d + e <= q; ++e) {
                    const int f = q - d - e, i = a + d, j = b + e, k = c + f;
                    const double w = binomial(i, a) * binomial(j, b) * binomial(k, c) / cnp;
                    out.at(i, j) = out.at(i, j) + w * v_blossoms[TriangularNet::index(q, d, e)];
                }
            ++terms;
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
