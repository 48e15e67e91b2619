// SPDX-License-Identifier: MIT
#include <seamless/tessellate/error_bound.h>

#include <algorithm>
#include <cassert>
#include <limits>

namespace seamless {
namespace {

double binomial(int n, int k) {
    double r = 1;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
    return r;
}

Vec3 bilinear(const std::array<Vec3, 4>& V, double s, double t) {
    return (1 - s) * (1 - t) * V[0] + s * (1 - t) * V[1] + s * t * V[2] + (1 - s) * t * V[3];
}

} // namespace

double bilinear_deviation(const BezierPatch& b) {
    const std::array<Vec3, 4> C{b.corner(0), b.corner(1), b.corner(2), b.corner(3)};
    const int p = b.p, q = b.q;
    double dev = 0;
    if (!b.rational) {
        for (int i = 0; i <= p; ++i)
            for (int j = 0; j <= q; ++j)
                dev = std::max(dev,
                               distance(b.point(i, j), bilinear(C, double(i) / p, double(j) / q)));
        return dev;
    }
    // Corner (a, c) of the degree (1,1) factor: C[0] (0,0), C[1] (1,0), C[2] (1,1), C[3] (0,1).
    auto corner = [&](int a, int c) { return C[a == 0 ? (c == 0 ? 0 : 3) : (c == 0 ? 1 : 2)]; };
    double wmin = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j) wmin = std::min(wmin, b.at(i, j).w);
    assert(wmin > 0);
    for (int k = 0; k <= p + 1; ++k)
        for (int l = 0; l <= q + 1; ++l) {
            Vec3 c{};
            for (int a = 0; a <= 1; ++a) {
                const int i = k - a;
                if (i < 0 || i > p) continue;
                const double al = binomial(p, i) / binomial(p + 1, k);
                for (int e = 0; e <= 1; ++e) {
                    const int j = l - e;
                    if (j < 0 || j > q) continue;
                    const double be = binomial(q, j) / binomial(q + 1, l);
                    const HPoint h = b.at(i, j);
                    c += (al * be) * (h.xyz() - h.w * corner(a, e));
                }
            }
            dev = std::max(dev, norm(c));
        }
    return dev / wmin;
}

double fan_deviation(const std::array<Vec3, 4>& V, Vec3 centre, std::span<const FanVertex> ring) {
    const Vec3 twist = V[0] - V[1] + V[2] - V[3];
    const double tw = norm(twist);
    const double centre_off = distance(centre, bilinear(V, 0.5, 0.5));
    const size_t n = ring.size();
    double dev = 0;
    for (size_t k = 0; k < n; ++k) {
        const FanVertex& a = ring[k];
        const FanVertex& b = ring[(k + 1) % n];
        // |L - F| is linear on the triangle: its largest vertex value.
        const double off = std::max({centre_off, distance(a.position, bilinear(V, a.s, a.t)),
                                     distance(b.position, bilinear(V, b.s, b.t))});
        // Interpolation error of s*t on the triangle (centre, a, b).
        const double pa = std::abs((a.s - 0.5) * (a.t - 0.5));
        const double pb = std::abs((b.s - 0.5) * (b.t - 0.5));
        const double ab = std::abs((a.s - b.s) * (a.t - b.t));
        dev = std::max(dev, off + tw * std::max({pa, pb, ab}) / 3.0);
    }
    return dev;
}

double rounding_allowance(int depth, double scale) {
    return (8.0 * (depth + 8)) * std::numeric_limits<double>::epsilon() * scale;
}

} // namespace seamless
