// SPDX-License-Identifier: MIT
// With M bilinear over the box (its corner values M_ab from the affine map
// continued), E = X - W M and W of bidegree (p + 1, q + 1):
//   e_ij = sum_{a, b in {0, 1}} c_a(i) d_b(j) (x_(i-a)(j-b) - w_(i-a)(j-b) M_ab),
//   c_1(i) = i / (p + 1), c_0(i) = 1 - c_1(i), d alike,
// so |S - M| <= max |e_ij| / w_ij over the box (bilinear_box.cpp). On the
// piece, M - L = A - L + T sigma tau (A affine, T = M_00 - M_10 - M_01 +
// M_11 the twist, sigma, tau in [0, 1] the box's own coordinates): A - L is
// affine on the piece, so |M - L| <= max_k |M(y_k) - L_k| + 2 |T|, whatever
// M's rounding.
#include <seamless/tessellate/trimmed/bounds/box_hull.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless {
namespace {

constexpr double kU = std::numeric_limits<double>::epsilon() / 2;
constexpr double kInf = std::numeric_limits<double>::infinity();

double magnitude(Vec3 v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

} // namespace

double box_hull_bound(const BoxNet& box, const std::array<Vec3, 3>& L) {
    const double s0 = box.s[0], t0 = box.t[0];
    const double a1 = box.s[1] - s0, b1 = box.t[1] - t0, a2 = box.s[2] - s0, b2 = box.t[2] - t0;
    const double det = a1 * b2 - b1 * a2;
    const double ws = box.s_hi - box.s_lo, wt = box.t_hi - box.t_lo;
    if (!(std::abs(det) > 0 && std::isfinite(det) && ws > 0 && wt > 0)) return kInf;
    // The affine map continued to the box's corners: M[a][b] at (s_a, t_b).
    auto continued = [&](double s, double t) {
        const double ds = s - s0, dt = t - t0;
        const double alpha = (ds * b2 - dt * a2) / det, beta = (a1 * dt - b1 * ds) / det;
        return L[0] + alpha * (L[1] - L[0]) + beta * (L[2] - L[0]);
    };
    const Vec3 M[2][2] = {{continued(box.s_lo, box.t_lo), continued(box.s_lo, box.t_hi)},
                          {continued(box.s_hi, box.t_lo), continued(box.s_hi, box.t_hi)}};
    double MM = 0, ML = 0, Mx = 0, Mw = 0;
    for (const auto& row : M)
        for (const Vec3& m : row) MM = std::max(MM, magnitude(m));
    for (const Vec3& l : L) ML = std::max(ML, magnitude(l));
    const int p = box.p, q = box.q;
    for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j)
            Mx = std::max(Mx, magnitude(box.at(i, j).xyz())),
            Mw = std::max(Mw, std::abs(box.at(i, j).w));
    // Each coefficient is a mean with positive weights of sum 1 of terms x - w M.
    const double err = box.error * (1 + MM) + 10 * kU * (Mx + Mw * MM);
    const double werr = box.error + 6 * kU * Mw;
    double worst = 0;
    for (int i = 0; i <= p + 1; ++i)
        for (int j = 0; j <= q + 1; ++j) {
            Vec3 e{0, 0, 0};
            double w = 0;
            for (int a = 0; a < 2; ++a)
                for (int b = 0; b < 2; ++b) {
                    const int ii = i - a, jj = j - b;
                    if (ii < 0 || ii > p || jj < 0 || jj > q) continue;
                    const double weight =
                        (a ? i : p + 1 - i) / double(p + 1) * ((b ? j : q + 1 - j) / double(q + 1));
                    const HPoint& x = box.at(ii, jj);
                    e = e + weight * (x.xyz() - x.w * M[a][b]);
                    w += weight * x.w;
                }
            if (!(w - werr > 0)) return kInf;
            worst = std::max(worst, (norm(e) + 1.8 * err) / (w - werr));
        }
    // How far M strays from L on the piece (the .cpp's head), its
    // evaluation's rounding within a few ulps of the values.
    double stray = 0;
    for (int k = 0; k < 3; ++k) {
        const double sg = (box.s[k] - box.s_lo) / ws, tg = (box.t[k] - box.t_lo) / wt;
        const Vec3 lo = M[0][0] + sg * (M[1][0] - M[0][0]), hi = M[0][1] + sg * (M[1][1] - M[0][1]);
        stray = std::max(stray, distance(lo + tg * (hi - lo), L[k]));
    }
    const double twist = norm(M[0][0] - M[1][0] - M[0][1] + M[1][1]);
    return (worst + stray + 2 * twist + 64 * kU * (MM + ML)) * (1 + 1e-12);
}

} // namespace seamless
