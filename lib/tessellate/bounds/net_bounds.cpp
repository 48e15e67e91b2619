// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/tessellate/bounds/error_bound.h>
#include <seamless/tessellate/bounds/net_bounds.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace seamless {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// A bicubic control net alone (a BezierPatch holds 10 x 10 points): the
// boxes the certified bound extracts from bicubic patches.
struct BicubicNet {
    static constexpr int kMaxOrder = 4;
    static constexpr int p = 3, q = 3;
    std::array<HPoint, 16> cp;
    HPoint& at(int i, int j) { return cp[i * 4 + j]; }
    const HPoint& at(int i, int j) const { return cp[i * 4 + j]; }
};

template <class Patch> Net make_net(const Patch& b, Vec3 c) {
    Net n;
    const int p = n.p = b.p, q = n.q = b.q;
    n.wlo = std::numeric_limits<double>::infinity();
    constexpr int O = Patch::kMaxOrder;
    // Only the entries (i <= p, j <= q) are written and read: not zeroed.
    std::array<std::array<double, 3>, O * O> x; // w (P - c)
    std::array<double, O * O> w;
    // With one weight throughout (a polynomial patch) the weights' differences
    // are exactly 0, so the points and first differences, which the quotient
    // rule multiplies only by them, are not needed: not stored (count 0, their
    // largest magnitude 0), the bounds unchanged. Saves most of the net.
    bool one_weight = true;
    for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j) one_weight = one_weight && b.at(i, j).w == b.at(0, 0).w;
    for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j) {
            const HPoint& h = b.at(i, j);
            const Vec3 v = h.xyz() - h.w * c;
            x[i * O + j] = {v.x, v.y, v.z};
            w[i * O + j] = h.w;
            if (!one_weight) n.add(Net::kP0, h.point() - c);
            n.wlo = std::min(n.wlo, h.w);
        }
    SEAMLESS_CHECK(n.wlo > 0, "a weight of the net is not positive");
    auto X = [&](int i, int j) {
        const std::array<double, 3>& v = x[i * O + j];
        return Vec3{v[0], v[1], v[2]};
    };
    auto W = [&](int i, int j) { return w[i * O + j]; };
    // Second and mixed differences (one weight: the weights' are exactly 0).
    for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j) {
            if (i + 1 < p) n.add(Net::kXss, X(i + 2, j) - 2 * X(i + 1, j) + X(i, j));
            if (j + 1 < q) n.add(Net::kXtt, X(i, j + 2) - 2 * X(i, j + 1) + X(i, j));
            if (i < p && j < q)
                n.add(Net::kXst, X(i + 1, j + 1) - X(i + 1, j) - X(i, j + 1) + X(i, j));
        }
    if (one_weight) return n;
    for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j) {
            if (i < p) {
                n.add(Net::kXs, X(i + 1, j) - X(i, j));
                n.Ws = std::max(n.Ws, std::abs(W(i + 1, j) - W(i, j)));
            }
            if (j < q) {
                n.add(Net::kXt, X(i, j + 1) - X(i, j));
                n.Wt = std::max(n.Wt, std::abs(W(i, j + 1) - W(i, j)));
            }
            if (i + 1 < p)
                n.Wss = std::max(n.Wss, std::abs(W(i + 2, j) - 2 * W(i + 1, j) + W(i, j)));
            if (j + 1 < q)
                n.Wtt = std::max(n.Wtt, std::abs(W(i, j + 2) - 2 * W(i, j + 1) + W(i, j)));
            if (i < p && j < q)
                n.Wst = std::max(n.Wst,
                                 std::abs(W(i + 1, j + 1) - W(i + 1, j) - W(i, j + 1) + W(i, j)));
        }
    n.Ws *= p, n.Wt *= q, n.Wss *= p * (p - 1), n.Wtt *= q * (q - 1), n.Wst *= p * q;
    return n;
}

// make_net of a bicubic net with one weight throughout (polynomial, or all
// weights equal): the same values in the same order, each coordinate apart
// in flat arrays, so the differences run two at a time and are stored in
// place (the general make_net's loops cost more than twice as much).
Net one_weight_bicubic_net(const BicubicNet& b, Vec3 c) {
    Net n;
    n.p = n.q = 3;
    n.wlo = std::numeric_limits<double>::infinity();
    alignas(16) double X[3][16]; // w (P - c), by coordinate
    for (int k = 0; k < 16; ++k) {
        const HPoint& h = b.cp[k];
        X[0][k] = h.x - h.w * c.x;
        X[1][k] = h.y - h.w * c.y;
        X[2][k] = h.z - h.w * c.z;
        n.wlo = std::min(n.wlo, h.w);
    }
    SEAMLESS_CHECK(n.wlo > 0, "a weight of the net is not positive");
    double* const out[3] = {n.dx.data(), n.dy.data(), n.dz.data()};
    for (int d = 0; d < 3; ++d) {
        const double* x = X[d];
        double* ss = out[d] + Net::kXss * Net::kN;
        double* tt = out[d] + Net::kXtt * Net::kN;
        double* st = out[d] + Net::kXst * Net::kN;
        for (int k = 0; k < 8; ++k)
            ss[k] = x[k + 8] - 2 * x[k + 4] + x[k]; // (i, j) = (k / 4, k % 4)
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 2; ++j)
                tt[i * 2 + j] = x[i * 4 + j + 2] - 2 * x[i * 4 + j + 1] + x[i * 4 + j];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                st[i * 3 + j] =
                    x[(i + 1) * 4 + j + 1] - x[(i + 1) * 4 + j] - x[i * 4 + j + 1] + x[i * 4 + j];
    }
    n.count[Net::kXss] = 8;
    n.count[Net::kXtt] = 8;
    n.count[Net::kXst] = 9;
    return n;
}

bool one_weight(const BicubicNet& b) {
    for (const HPoint& h : b.cp)
        if (h.w != b.cp[0].w) return false;
    return true;
}

template <size_t M> using Tops = std::array<std::array<double, M>, Net::kGroups>;

// The bounds from the largest magnitudes of each group of differences.
template <size_t M>
std::array<DerivativeBounds, M> derivative_bounds_from(const Net& n, const Tops<M>& top) {
    const int p = n.p, q = n.q;
    const double Ws = n.Ws, Wt = n.Wt, Wss = n.Wss, Wst = n.Wst, Wtt = n.Wtt;
    // Rounding of the differences and products: relative, a few ulps each.
    const double inflate = 1 + 64 * kEps;
    std::array<DerivativeBounds, M> out;
    for (size_t k = 0; k < M; ++k) {
        const double xs = top[Net::kXs][k] * p, xt = top[Net::kXt][k] * q;
        const double xss = top[Net::kXss][k] * (p * (p - 1));
        const double xtt = top[Net::kXtt][k] * (q * (q - 1)), xst = top[Net::kXst][k] * (p * q);
        const double p0 = top[Net::kP0][k];
        const double Ps = (xs + p0 * Ws) / n.wlo, Pt = (xt + p0 * Wt) / n.wlo;
        DerivativeBounds& r = out[k];
        r.A = (xss + 2 * Ps * Ws + p0 * Wss) / n.wlo * inflate;
        r.B = (xst + Ps * Wt + Pt * Ws + p0 * Wst) / n.wlo * inflate;
        r.C = (xtt + 2 * Pt * Wt + p0 * Wtt) / n.wlo * inflate;
    }
    return out;
}

// split_u / split_v (bezier_patch.h) of a bicubic net at s, keeping one part:
// the same operations in the same order, so the same points.
void split_bicubic(BicubicNet& b, double s, bool in_u, bool upper) {
    for (int j = 0; j < 4; ++j) {
        HPoint col[4], out[4];
        for (int i = 0; i < 4; ++i) col[i] = in_u ? b.at(i, j) : b.at(j, i);
        for (int level = 0; level <= 3; ++level) {
            if (upper)
                out[3 - level] = col[3 - level];
            else
                out[level] = col[0];
            for (int i = 0; i < 3 - level; ++i) col[i] = lerp(col[i], col[i + 1], s);
        }
        for (int i = 0; i < 4; ++i) (in_u ? b.at(i, j) : b.at(j, i)) = out[i];
    }
}

// extract_box of a bicubic patch, as a net alone (the same points).
BicubicNet extract_bicubic(const BezierPatch& patch, double s0, double s1, double t0, double t1) {
    BicubicNet b;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) b.at(i, j) = patch.at(i, j);
    if (s0 > 0) split_bicubic(b, s0, true, true);
    if (s1 < 1) split_bicubic(b, (s1 - s0) / (1 - s0), true, false);
    if (t0 > 0) split_bicubic(b, t0, false, true);
    if (t1 < 1) split_bicubic(b, (t1 - t0) / (1 - t0), false, false);
    return b;
}

} // namespace

Net net_of(const BezierPatch& b, Vec3 c) {
    if (b.p != 3 || b.q != 3) return make_net(b, c);
    BicubicNet n;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) n.at(i, j) = b.at(i, j);
    return one_weight(n) ? one_weight_bicubic_net(n, c) : make_net(n, c);
}

// M magnitudes of each difference at once (mag returns M values): the normal
// and the tangential bounds in one pass over the differences.
Net box_net(const BezierPatch& patch, double s0, double s1, double t0, double t1, Vec3 c) {
    if (patch.p == 3 && patch.q == 3) {
        const BicubicNet b = extract_bicubic(patch, s0, s1, t0, t1);
        return one_weight(b) ? one_weight_bicubic_net(b, c) : make_net(b, c);
    }
    return make_net(extract_box(patch, s0, s1, t0, t1), c);
}

DerivativeBounds derivative_bounds(const Net& n) {
    // Each group's largest norm as the root of its largest square (the root
    // is monotone and correctly rounded: the same value), one root per group
    // rather than one per difference (a bicubic net: 6 roots, not 25).
    Tops<1> top{};
    for (int g = 0; g < Net::kGroups; ++g) {
        double largest = 0;
        for (int i = 0; i < n.count[g]; ++i) {
            const Vec3 v = n.at(g, i);
            largest = std::max(largest, dot(v, v));
        }
        top[g][0] = std::sqrt(largest);
    }
    return derivative_bounds_from<1>(n, top)[0];
}

namespace {

// Per difference v: |v . n| and |v - (v . n) n| (a unit n), L differences at
// a time (vector extension; each lane does dot() and norm()'s operations in
// their order). The largest norm is the root of the largest square (the root
// is monotone and correctly rounded: the same value); a maximum does not
// depend on the order its candidates come in, so any L gives the same tops.
template <int L> struct LanesOf;
template <> struct LanesOf<2> { using type = double __attribute__((vector_size(16))); };
template <> struct LanesOf<4> { using type = double __attribute__((vector_size(32))); };

template <int L> [[gnu::always_inline]] inline Tops<2> split_tops(const Net& net, Vec3 n) {
    using Lanes = typename LanesOf<L>::type;
    Lanes nx, ny, nz;
    for (int l = 0; l < L; ++l) nx[l] = n.x, ny[l] = n.y, nz[l] = n.z;
    Tops<2> top{};
    for (int g = 0; g < Net::kGroups; ++g) {
        const int base = g * Net::kN, count = net.count[g];
        Lanes tn = {}, tt = {};
        int i = 0;
        for (; i + L - 1 < count; i += L) {
            Lanes x, y, z;
            std::memcpy(&x, &net.dx[base + i], sizeof x);
            std::memcpy(&y, &net.dy[base + i], sizeof y);
            std::memcpy(&z, &net.dz[base + i], sizeof z);
            const Lanes d = x * nx + y * ny + z * nz;
            const Lanes ad = d < 0 ? -d : d;
            const Lanes tx = x - d * nx, ty = y - d * ny, tz = z - d * nz;
            const Lanes t2 = tx * tx + ty * ty + tz * tz;
            tn = tn < ad ? ad : tn;
            tt = tt < t2 ? t2 : tt;
        }
        double mn = tn[0], mt = tt[0];
        for (int l = 1; l < L; ++l) mn = std::max(mn, tn[l]), mt = std::max(mt, tt[l]);
        for (; i < count; ++i) {
            const Vec3 v = net.at(g, i);
            const double d = dot(v, n);
            mn = std::max(mn, std::abs(d));
            mt = std::max(mt, dot(v - d * n, v - d * n));
        }
        top[g] = {mn, std::sqrt(mt)};
    }
    return top;
}

// Four lanes in one AVX2 instruction where the processor has it; two SSE2
// lanes elsewhere (four would cost more there than two).
[[gnu::target("avx2")]] Tops<2> split_tops_avx2(const Net& net, Vec3 n) {
    return split_tops<4>(net, n);
}
Tops<2> split_tops_sse2(const Net& net, Vec3 n) {
    return split_tops<2>(net, n);
}

} // namespace

SplitBounds split_bounds(const Net& net, Vec3 n) {
    if (!(norm(n) > 0)) {
        const DerivativeBounds full = derivative_bounds(net);
        return {full, full};
    }
    static const bool avx2 = __builtin_cpu_supports("avx2");
    const Tops<2> top = avx2 ? split_tops_avx2(net, n) : split_tops_sse2(net, n);
    const std::array<DerivativeBounds, 2> b = derivative_bounds_from<2>(net, top);
    return {b[0], b[1]};
}

} // namespace seamless
