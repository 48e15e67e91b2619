// SPDX-License-Identifier: MIT
#include <seamless/interval/interval.h>
#include <seamless/spline/enclosure/triangle_restriction.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless {
namespace {

constexpr double kU = std::numeric_limits<double>::epsilon() / 2; // unit roundoff
constexpr int K = BezierPatch::kMaxOrder;

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

// How much a step (1 - x) a + x b can grow a value or an earlier error.
double step_weight(double x) {
    return std::abs(1 - x) + std::abs(x);
}

// The corners of the triangle along one parameter: the smallest value a, the
// largest b and the third corner's place between them, x_mid = (1 - gamma) a
// + gamma b with gamma in [0, 1].
struct CornerOrder {
    int lo = 0, hi = 0, mid = 0;
    double gamma = 0;
    explicit CornerOrder(const std::array<double, 3>& x) {
        lo = static_cast<int>(std::min_element(x.begin(), x.end()) - x.begin());
        hi = static_cast<int>(std::max_element(x.begin(), x.end()) - x.begin());
        if (lo == hi) hi = (lo + 1) % 3; // all three equal
        mid = 3 - lo - hi;
        gamma = x[hi] > x[lo] ? (x[mid] - x[lo]) / (x[hi] - x[lo]) : 0;
    }
    // Where the blossom value with the corners' multiplicities e sits in the
    // pyramid (pyramid below): its level and its index there.
    int at(int m, const int (&e)[3]) const { return TriangularNet::index(m, e[mid], e[hi]); }
};

// The control points pts[0], pts[stride], ..., pts[m * stride] of a curve
// over [0, 1], in place, to those over [a, b] (a <= b): pts[i] becomes the
// blossom f(a^(m-i) b^i). Two de Casteljau splits, the first at the end
// farther from 0 or 1 respectively so that the second's parameter (rounded:
// the curve's blossom at a point a few ulps off a or b) has no division by
// zero. Returns the steps' growth (step_weight) over one value's chain.
double restrict_curve(HPoint* pts, int stride, int m, double a, double b) {
    auto at = [&](int i) -> HPoint& { return pts[i * stride]; };
    if (std::abs(b) >= std::abs(1 - a)) {
        // Over [0, b] (b > 0 here), then [a, b] at a / b of it.
        const double r = a / b;
        for (int l = 1; l <= m; ++l)
            for (int i = m; i >= l; --i) at(i) = lerp(at(i - 1), at(i), b);
        for (int l = 1; l <= m; ++l)
            for (int i = 0; i + l <= m; ++i) at(i) = lerp(at(i), at(i + 1), r);
        return std::pow(step_weight(b) * step_weight(r), m);
    }
    // Over [a, 1] (a < 1 here), then [a, b] at (b - a) / (1 - a) of it.
    const double r = (b - a) / (1 - a);
    for (int l = 1; l <= m; ++l)
        for (int i = 0; i + l <= m; ++i) at(i) = lerp(at(i), at(i + 1), a);
    for (int l = 1; l <= m; ++l)
        for (int i = m; i >= l; --i) at(i) = lerp(at(i - 1), at(i), r);
    return std::pow(step_weight(a) * step_weight(r), m);
}

// From the control points over [a, b] of a curve of degree m (stride apart),
// de Casteljau's pyramid at gamma: level c, index i is the blossom
// f(a^(m-i-c) b^i x^c), x = (1 - gamma) a + gamma b, into
// out[TriangularNet::index(m, c, i)]. So every blossom at the three corners'
// values comes from m (m + 1) / 2 steps, in [0, 1].
void pyramid(const HPoint* pts, int stride, int m, double gamma, HPoint* out) {
    for (int i = 0; i <= m; ++i) out[i] = pts[i * stride];
    for (int c = 1; c <= m; ++c) {
        const HPoint* from = out + TriangularNet::index(m, c - 1, 0);
        HPoint* to = out + TriangularNet::index(m, c, 0);
        for (int i = 0; i + c <= m; ++i) to[i] = lerp(from[i], from[i + 1], gamma);
    }
}

// The gathering of restrict_to_triangle for degrees (p, q): for the
// u-blossom ab and the v-blossom de (each in the loop order (a, b), (d, e)),
// the coefficient b_ijk they add to and their weight C(i,a) C(j,b) C(k,c) /
// C(n,p) (header). Kept per thread for the last degrees asked.
struct Gather {
    int p = -1, q = -1;
    std::array<int, K*(K + 1) / 2 * K*(K + 1) / 2> place;
    std::array<double, K*(K + 1) / 2 * K*(K + 1) / 2> weight;
};

const Gather& gather(int p, int q) {
    static thread_local Gather g;
    if (g.p == p && g.q == q) return g;
    g.p = p, g.q = q;
    const int n = p + q;
    const double cnp = binomial(n, p);
    int at = 0;
    for (int a = 0; a <= p; ++a)
        for (int b = 0; a + b <= p; ++b)
            for (int d = 0; d <= q; ++d)
                for (int e = 0; d + e <= q; ++e, ++at) {
                    const int c = p - a - b, f = q - d - e, i = a + d, j = b + e, k = c + f;
                    g.place[at] = TriangularNet::index(n, i, j);
                    g.weight[at] = binomial(i, a) * binomial(j, b) * binomial(k, c) / cnp;
                }
    return g;
}

} // namespace

// The blossom values f(s-multiset; t-multiset) over the triangle's corners:
// the patch restricted to the corners' (s, t) bounding box (restrict_curve
// on its columns, then its rows: restrict_to_box), then in each direction
// one pyramid at the third corner (every corner value is an affine
// combination of the smallest and largest: the blossom is affine in each
// argument; box_to_triangle).
//
// Rounding. Let M bound every homogeneous coordinate of the control points
// and g >= |1 - x| + |x| for every corner coordinate x (g = 1 inside
// [0,1]^2): every value computed is a blossom at such arguments, below g^n
// M. A step in doubles errs by at most 5.1 u times its growth (step_weight)
// times that (u = 2^-53) and passes earlier errors on with that growth, so
// the 3 n steps of a value (2 p for the box and p for the pyramid in s, q
// alike) err by at most 5.1 (3 n) u g^n M G, G the steps' growths
// multiplied along one chain (1 inside [0,1]^2); the box's values after 2 n
// steps. The sum over the T terms with positive weights of sum 1 (each
// weight within u of its value) adds (T + 2) u g^n G M. Gradual underflow:
// underflow_allowance (interval.h). The rounded split and pyramid
// parameters make the values those of the blossom at arguments a few ulps
// off the corners' (a' = b fl(a / b) within u |a|, b' within 6.2 u max(|a|,
// |b|) likewise, the third corner within that and 3.1 u |b - a| more): the
// coefficients over that moved triangle or box, its corners within 16 u
// max |s|, |t| (header).
void restrict_to_box(const BezierPatch& patch, const std::array<std::array<double, 2>, 3>& st,
                     BoxNet& out) {
    const int p = patch.p, q = patch.q, n = p + q;
    out.p = p, out.q = q;
    for (int k = 0; k < 3; ++k) out.s[k] = st[k][0], out.t[k] = st[k][1];
    const CornerOrder os(out.s), ot(out.t);
    out.s_lo = out.s[os.lo], out.s_hi = out.s[os.hi], out.t_lo = out.t[ot.lo],
    out.t_hi = out.t[ot.hi];
    HPoint* box = out.b.data();
    for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j) box[i * K + j] = patch.at(i, j);
    double growth_u = 1, growth_v = 1;
    for (int j = 0; j <= q; ++j) growth_u = restrict_curve(&box[j], K, p, out.s_lo, out.s_hi);
    for (int i = 0; i <= p; ++i) growth_v = restrict_curve(&box[i * K], 1, q, out.t_lo, out.t_hi);
    out.M = 0;
    for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j)
            for (int c = 0; c < 4; ++c) out.M = std::max(out.M, std::abs(patch.at(i, j)[c]));
    double wide = 1;
    for (int k = 0; k < 3; ++k)
        wide = std::max({wide, step_weight(out.s[k]), step_weight(out.t[k])});
    out.grow = std::pow(wide, n) * growth_u * growth_v * (1 + 1e-10);
    out.error = (5.1 * 2 * n * kU * out.M * out.grow + underflow_allowance(32 * n * out.grow)) *
                (1 + 1e-10);
}

void box_to_triangle(const BoxNet& box, TriangularNet& out) {
    const int p = box.p, q = box.q, n = p + q;
    const CornerOrder os(box.s), ot(box.t);
    static thread_local std::array<HPoint, K*(K + 1) / 2 * K> U;
    std::array<HPoint, K*(K + 1) / 2> V;
    std::array<HPoint, K> row;
    // U: column j's pyramid at (j * (p + 1) (p + 2) / 2).
    const int su = (p + 1) * (p + 2) / 2;
    for (int j = 0; j <= q; ++j) pyramid(&box.b[j], K, p, os.gamma, &U[j * su]);
    out.n = n;
    std::fill(out.b.begin(), out.b.begin() + TriangularNet::index(n, n, 0) + 1, HPoint{0, 0, 0, 0});
    // b_ijk gathers the v-blossoms of every u-blossom (a, b, c) at
    // t_0^(i-a) t_1^(j-b) t_2^(k-c) with its weight (header).
    const Gather& g = gather(p, q);
    std::array<int, K*(K + 1) / 2> at_v; // (d, e) to its place in V
    for (int d = 0, de = 0; d <= q; ++d)
        for (int e = 0; d + e <= q; ++e, ++de) {
            const int ev[3] = {d, e, q - d - e};
            at_v[de] = ot.at(q, ev);
        }
    const int sv = (q + 1) * (q + 2) / 2;
    for (int a = 0, ab = 0; a <= p; ++a)
        for (int b = 0; a + b <= p; ++b, ++ab) {
            const int eu[3] = {a, b, p - a - b};
            const int at_u = os.at(p, eu);
            for (int l = 0; l <= q; ++l) row[l] = U[l * su + at_u];
            pyramid(row.data(), 1, q, ot.gamma, V.data());
            const int* place = &g.place[ab * sv];
            const double* weight = &g.weight[ab * sv];
            for (int de = 0; de < sv; ++de)
                out.b[place[de]] = out.b[place[de]] + weight[de] * V[at_v[de]];
        }
    const int terms = su;
    out.error = ((5.1 * 3 * n + terms + 2) * kU * box.M * box.grow +
                 underflow_allowance(48 * n * box.grow)) *
                (1 + 1e-10);
}

void restrict_to_triangle(const BezierPatch& patch, const std::array<std::array<double, 2>, 3>& st,
                          TriangularNet& out) {
    static thread_local BoxNet box;
    restrict_to_box(patch, st, box);
    box_to_triangle(box, out);
}

} // namespace seamless
