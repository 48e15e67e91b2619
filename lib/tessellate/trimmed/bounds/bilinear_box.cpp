// SPDX-License-Identifier: MIT
// TriangleBound::bilinear_box (triangle_bound.h): the rectangle cut along
// the knot lines into cells, each one Bezier patch; on a cell the patch's
// coefficients over it enclosed in interval arithmetic (subpatch.h: de
// Casteljau on intervals), and with M bilinear, E = X - W M and W of
// bidegree (p + 1, q + 1):
//   e_ij = sum_{a, b in {0, 1}} c_a(i) d_b(j) (x_(i-a)(j-b) - w_(i-a)(j-b) M_ab),
//   c_1(i) = i / (p + 1), c_0(i) = 1 - c_1(i), d alike,
// so |S - M| <= max |e_ij| / w_ij over the cell (the convex hull property
// of the rational patch E / W, as in triangle_bound.h).
#include <seamless/interval/interval_matrix.h>
#include <seamless/spline/enclosure/subpatch.h>
#include <seamless/tessellate/trimmed/bounds/triangle_bound.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace seamless {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Where x lies between lo and hi, as an interval holding the exact ratio.
Interval ratio(double x, double lo, double hi) {
    return (Interval(x) - Interval(lo)) / (Interval(hi) - Interval(lo));
}

// The bilinear map with corner values M (triangle_bound.h's order) at the
// fractions (a, b) of the rectangle.
IVec<3> bilinear(const std::array<Vec3, 4>& M, Interval a, Interval b) {
    IVec<3> out;
    for (int c = 0; c < 3; ++c) {
        const Interval lo = (1.0 - a) * Interval(M[0][c]) + a * Interval(M[1][c]);
        const Interval hi = (1.0 - a) * Interval(M[3][c]) + a * Interval(M[2][c]);
        out[c] = (1.0 - b) * lo + b * hi;
    }
    return out;
}

// max |e_ij| / w_ij (header) for the coefficients c of the cell and the
// values Mc of M at its corners (a: 0 at s = 0, 1 at s = 1; b alike).
double cell_hull(const Interval* c, SubpatchShape sh, const IVec<3> (&Mc)[2][2]) {
    const int p = sh.p, q = sh.q;
    double worst = 0;
    for (int i = 0; i <= p + 1; ++i)
        for (int j = 0; j <= q + 1; ++j) {
            Interval e[3] = {0.0, 0.0, 0.0}, w = 0.0;
            for (int a = 0; a < 2; ++a)
                for (int b = 0; b < 2; ++b) {
                    const int ii = i - a, jj = j - b;
                    if (ii < 0 || ii > p || jj < 0 || jj > q) continue;
                    const Interval ca =
                        a ? Interval(i) / Interval(p + 1) : Interval(p + 1 - i) / Interval(p + 1);
                    const Interval db =
                        b ? Interval(j) / Interval(q + 1) : Interval(q + 1 - j) / Interval(q + 1);
                    const Interval weight = ca * db;
                    const Interval wk = sh.dim == 4 ? c[sh.index(3, ii, jj)] : Interval(1.0);
                    for (int k = 0; k < 3; ++k)
                        e[k] = e[k] + weight * (c[sh.index(k, ii, jj)] - wk * Mc[a][b][k]);
                    w = w + weight * wk;
                }
            if (!(w.lo() > 0)) return kInf;
            const Interval n2 = sqr(e[0]) + sqr(e[1]) + sqr(e[2]);
            worst = std::max(worst, (sqrt(n2) / w).hi());
        }
    return worst;
}

} // namespace

double TriangleBound::bilinear_box(const std::array<double, 4>& box,
                                   const std::array<Vec3, 4>& M) const {
    const double u0 = box[0], u1 = box[1], v0 = box[2], v1 = box[3];
    if (!(u0 < u1 && v0 < v1)) return kInf;
    // A box a rounding past the domain (a file's seam a few ulps off): S is
    // taken at the clamped point there, so the mesh's change across the
    // overhang adds to the bound.
    const double du = std::max({0.0, u_.lo() - u0, u1 - u_.hi()}),
                 dv = std::max({0.0, v_.lo() - v0, v1 - v_.hi()});
    if (!(du <= 1e-9 * (u_.hi() - u_.lo()) && dv <= 1e-9 * (v_.hi() - v_.lo()))) return kInf;
    const double overhang =
        (std::max(distance(M[1], M[0]), distance(M[2], M[3])) * du / (u1 - u0) +
         std::max(distance(M[3], M[0]), distance(M[2], M[1])) * dv / (v1 - v0)) *
        (1 + 1e-12);
    // The box clamped to the domain, cut at the knots inside it; a box a
    // rounding past the domain's end clamps to no width: no cell bounds it.
    const double a0 = std::max(u0, u_.lo()), a1 = std::min(u1, u_.hi()), b0 = std::max(v0, v_.lo()),
                 b1 = std::min(v1, v_.hi());
    if (!(a0 < a1 && b0 < b1)) return kInf;
    std::vector<double> us{a0}, vs{b0};
    for (double k : u_.at)
        if (k > a0 && k < a1) us.push_back(k);
    for (double k : v_.at)
        if (k > b0 && k < b1) vs.push_back(k);
    us.push_back(a1), vs.push_back(b1);
    const int nv = static_cast<int>(v_.at.size()) - 1;
    std::vector<Interval> c;
    double worst = 0;
    for (size_t a = 0; a + 1 < us.size(); ++a)
        for (size_t b = 0; b + 1 < vs.size(); ++b) {
            double shift = 0;
            const int iu = span_of(u_, (us[a] + us[a + 1]) / 2, shift);
            const int iv = span_of(v_, (vs[b] + vs[b + 1]) / 2, shift);
            const BezierPatch& patch = patches_[iu * nv + iv];
            const SubpatchShape sh = subpatch_shape(patch);
            c.resize(sh.size());
            control_coefficients(patch, sh, c.data());
            restrict_subpatch(c.data(), sh, 0, ratio(us[a], patch.u0, patch.u1),
                              ratio(us[a + 1], patch.u0, patch.u1));
            restrict_subpatch(c.data(), sh, 1, ratio(vs[b], patch.v0, patch.v1),
                              ratio(vs[b + 1], patch.v0, patch.v1));
            IVec<3> Mc[2][2];
            for (int i = 0; i < 2; ++i)
                for (int j = 0; j < 2; ++j)
                    Mc[i][j] = bilinear(M, ratio(us[a + i], u0, u1), ratio(vs[b + j], v0, v1));
            worst = std::max(worst, cell_hull(c.data(), sh, Mc));
            if (!(worst < kInf)) return kInf;
        }
    return worst + overhang;
}

} // namespace seamless
