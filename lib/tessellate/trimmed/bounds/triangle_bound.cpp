// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/spline/enclosure/triangle_restriction.h>
#include <seamless/spline/knot_insertion.h>
#include <seamless/tessellate/trimmed/bounds/beyond_side.h>
#include <seamless/tessellate/trimmed/bounds/box_hull.h>
#include <seamless/tessellate/trimmed/bounds/triangle_bound.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless {
namespace {

constexpr double kU = std::numeric_limits<double>::epsilon() / 2; // unit roundoff
constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<double> distinct_knots(const std::vector<double>& U, double lo, double hi) {
    std::vector<double> out;
    for (double t : U)
        if (t >= lo && t <= hi && (out.empty() || out.back() != t)) out.push_back(t);
    return out;
}

// max_a |e_a| / w_a over the coefficients of E = X - W L and W (header), L
// the affine map with the values Lj at the piece's corners: at degree
// n + 1, e_a = sum_k (a_k / m) (x_{a-k} - w_{a-k} L_k) and w_a =
// sum_k (a_k / m) w_{a-k} (degree elevation and the product with a degree-1
// polynomial, m = n + 1); then raised to degree 2 (n + 1) (at most
// TriangularNet's), where the hull overestimates the largest |E / W| by a
// factor near m / (m - 1) instead of (n + 1) / n (the cylinder: 1.33 to
// 1.14). Rounding: every step is a mean with positive weights of sum 1, so
// e_a and w_a err by at most the net's error and 8u of their terms'
// magnitudes at the product, and 4u of them per elevation.
//
// The hull at every degree bounds |E / W| (each elevation takes means, so it
// only tightens): where the hull at degree n + 1 or halfway up is already at
// most `cutoff`, that one is returned and the rest of the elevation is
// skipped. Each check counts the rounding of the full elevation (more than
// its own).
double hull_bound(const TriangularNet& net, const std::array<Vec3, 3>& Lj, double cutoff) {
    const int n = net.n;
    const int top = std::min(2 * (n + 1), TriangularNet::kMaxOrder - 1);
    double Mx = 0, Mw = 0, ML = 0;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
            const HPoint& b = net.at(i, j);
            Mx = std::max({Mx, std::abs(b.x), std::abs(b.y), std::abs(b.z)});
            Mw = std::max(Mw, std::abs(b.w));
        }
    for (const Vec3& L : Lj) ML = std::max({ML, std::abs(L.x), std::abs(L.y), std::abs(L.z)});
    const int steps = top - n;
    const double err = net.error * (1 + ML) + (8 + 4 * steps) * kU * (Mx + Mw * ML);
    const double werr = net.error + (4 + 4 * steps) * kU * Mw;
    // (e, w) as HPoints, raised from degree d in `from` to d + 1 in `to`.
    static thread_local std::array<HPoint,
                                   TriangularNet::kMaxOrder*(TriangularNet::kMaxOrder + 1) / 2>
        buf[2];
    auto raise = [](int d, const HPoint* from, HPoint* to) {
        const int m = d + 1;
        for (int i = 0; i <= m; ++i)
            for (int j = 0; i + j <= m; ++j) {
                const int k = m - i - j;
                HPoint sum{0, 0, 0, 0};
                if (i > 0) sum = sum + (double(i) / m) * from[TriangularNet::index(d, i - 1, j)];
                if (j > 0) sum = sum + (double(j) / m) * from[TriangularNet::index(d, i, j - 1)];
                if (k > 0) sum = sum + (double(k) / m) * from[TriangularNet::index(d, i, j)];
                to[TriangularNet::index(m, i, j)] = sum;
            }
    };
    auto hull = [&](int d, const HPoint* c) {
        double worst = 0;
        for (int a = 0; a <= TriangularNet::index(d, d, 0); ++a) {
            const double low = c[a].w - werr;
            if (!(low > 0)) return kInf;
            worst = std::max(worst, (norm(c[a].xyz()) + 1.8 * err) / low);
        }
        return worst * (1 + 1e-12);
    };
    // The product: from the net's X and W to (e, w) at degree n + 1, the
    // mesh value of each term by the corner its index grew at.
    {
        const int m = n + 1;
        for (int i = 0; i <= m; ++i)
            for (int j = 0; i + j <= m; ++j) {
                const int k = m - i - j;
                HPoint sum{0, 0, 0, 0};
                auto term = [&](int count, int bi, int bj, Vec3 L) {
                    if (count == 0) return;
                    const HPoint& b = net.at(bi, bj);
                    const Vec3 e = b.xyz() - b.w * L;
                    sum = sum + (double(count) / m) * HPoint{e.x, e.y, e.z, b.w};
                };
                term(i, i - 1, j, Lj[0]);
                term(j, i, j - 1, Lj[1]);
                term(k, i, j, Lj[2]);
                buf[0][TriangularNet::index(m, i, j)] = sum;
            }
    }
    const int halfway = (n + 1 + top) / 2;
    int cur = 0;
    for (int d = n + 1; d < top; ++d, cur ^= 1) {
        if (d == n + 1 || d == halfway) {
            const double early = hull(d, buf[cur].data());
            if (early <= cutoff) return early;
        }
        raise(d, buf[cur].data(), buf[cur ^ 1].data());
    }
    return hull(top, buf[cur].data());
}

} // namespace

TriangleBound::TriangleBound(const BSplineSurface& s, bool closed_u, bool closed_v)
    : patches_(bezier_patches(s, -1)) {
    u_.at = distinct_knots(s.knots_u, s.u_min(), s.u_max());
    v_.at = distinct_knots(s.knots_v, s.v_min(), s.v_max());
    u_.closed = closed_u, v_.closed = closed_v;
    SEAMLESS_CHECK(patches_.size() == (u_.at.size() - 1) * (v_.at.size() - 1),
                   "one Bezier patch per pair of knot spans");
    // |S_s| <= 2 p^2 (w_max / w_min) max |P_i+1 - P_i| (S_s = (X_s - S W_s) / W
    // with X_s - S W_s = p sum B_i (w_i+1 (P_i+1 - S) - w_i (P_i - S)), and
    // |P_i - S| below the net's extent): only the rounding terms use it.
    for (const BezierPatch& b : patches_) {
        double wmin = kInf, wmax = 0, du = 0, dv = 0;
        for (int i = 0; i <= b.p; ++i)
            for (int j = 0; j <= b.q; ++j) {
                wmin = std::min(wmin, b.at(i, j).w), wmax = std::max(wmax, b.at(i, j).w);
                if (i < b.p) du = std::max(du, distance(b.point(i + 1, j), b.point(i, j)));
                if (j < b.q) dv = std::max(dv, distance(b.point(i, j + 1), b.point(i, j)));
            }
        const double ratio = wmin > 0 ? wmax / wmin : kInf;
        gradient_.push_back(
            2 * ratio * std::max(b.p * b.p * du / (b.u1 - b.u0), b.q * b.q * dv / (b.v1 - b.v0)));
    }
}

double TriangleBound::max_gradient() const {
    return gradient_.empty() ? 0 : *std::max_element(gradient_.begin(), gradient_.end());
}

int TriangleBound::span_of(const Axis& a, double x, double& shift) const {
    shift = 0;
    if (a.closed) {
        const double period = a.hi() - a.lo();
        shift = std::floor((x - a.lo()) / period) * period;
        x -= shift;
    }
    const int spans = static_cast<int>(a.at.size()) - 1;
    const int i =
        static_cast<int>(std::upper_bound(a.at.begin(), a.at.end(), x) - a.at.begin()) - 1;
    return std::clamp(i, 0, spans - 1);
}

void TriangleBound::cuts(const Axis& a, double lo, double hi, std::vector<double>& out) const {
    out.clear();
    if (!a.closed) {
        for (double k : a.at)
            if (k > lo && k < hi) out.push_back(k);
        return;
    }
    const double period = a.hi() - a.lo();
    for (double shift = std::floor((lo - a.lo()) / period) * period; a.lo() + shift < hi;
         shift += period)
        for (size_t i = 0; i + 1 < a.at.size(); ++i)
            if (a.at[i] + shift > lo && a.at[i] + shift < hi) out.push_back(a.at[i] + shift);
}

double TriangleBound::piece_bound(const TrianglePiece& piece, const BezierPatch& patch,
                                  double shift_u, double shift_v, const std::array<Vec3, 3>& Q,
                                  double cutoff) const {
    std::array<std::array<double, 2>, 3> st;
    std::array<Vec3, 3> L;
    double hu = 0, hv = 0; // overhang beyond an open side
    for (int j = 0; j < 3; ++j) {
        const PieceCorner& c = piece.corner[j];
        st[j] = {(c.uv[0] - shift_u - patch.u0) / (patch.u1 - patch.u0),
                 (c.uv[1] - shift_v - patch.v0) / (patch.v1 - patch.v0)};
        L[j] = c.lambda[0] * Q[0] + c.lambda[1] * Q[1] + c.lambda[2] * Q[2];
        if (!u_.closed) hu = std::max({hu, u_.lo() - c.uv[0], c.uv[0] - u_.hi()});
        if (!v_.closed) hv = std::max({hv, v_.lo() - c.uv[1], c.uv[1] - v_.hi()});
    }
    const double side = hu == 0 && hv == 0 ? 0 : beyond_side(patch, st, hu, hv);
    if (!(side < kInf)) return kInf;
    // The box stage first: above degree 4, where the triangle's stage costs
    // most, the box's looser hull may already be below the cutoff.
    static thread_local BoxNet box; // 3 KB: not cleared per piece
    restrict_to_box(patch, st, box);
    if (cutoff - side > 0 && patch.p + patch.q > 4) {
        const double early = box_hull_bound(box, L);
        if (early <= cutoff - side) return early + side;
    }
    static thread_local TriangularNet net; // 7 KB
    box_to_triangle(box, net);
    return hull_bound(net, L, cutoff - side) + side;
}

double TriangleBound::operator()(const std::array<UV, 3>& uv, const std::array<Vec3, 3>& Q,
                                 double cutoff) const {
    double lo[2] = {kInf, kInf}, hi[2] = {-kInf, -kInf}, far = 0, qmax = 0;
    for (const UV& x : uv)
        for (int a = 0; a < 2; ++a)
            lo[a] = std::min(lo[a], x[a]), hi[a] = std::max(hi[a], x[a]),
            far = std::max(far, std::abs(x[a]));
    for (const Vec3& q : Q) qmax = std::max({qmax, std::abs(q.x), std::abs(q.y), std::abs(q.z)});
    struct Placed {
        int patch;
        double shift_u, shift_v;
    };
    thread_local std::vector<double> cu, cv;
    thread_local std::vector<TrianglePiece> pieces;
    thread_local std::vector<Placed> placed;
    cuts(u_, lo[0], hi[0], cu);
    cuts(v_, lo[1], hi[1], cv);
    pieces.clear();
    placed.clear();
    cut_triangle(uv, cu, cv, pieces);
    // The cell's middle names its patch and period.
    auto middle = [&](int axis, int cell, const std::vector<double>& c) {
        const double a = cell > 0 ? c[cell - 1] : lo[axis];
        const double b = cell < static_cast<int>(c.size()) ? c[cell] : hi[axis];
        return (a + b) / 2;
    };
    const int nv = static_cast<int>(v_.at.size()) - 1;
    double gradient = 0, local = 0;
    for (const TrianglePiece& piece : pieces) {
        Placed at{0, 0, 0};
        const int iu = span_of(u_, middle(0, piece.cell_u, cu), at.shift_u);
        const int iv = span_of(v_, middle(1, piece.cell_v, cv), at.shift_v);
        at.patch = iu * nv + iv;
        placed.push_back(at);
        gradient = std::max(gradient, gradient_[at.patch]);
        const BezierPatch& b = patches_[at.patch];
        for (const PieceCorner& c : piece.corner)
            local = std::max(local, std::abs(c.uv[0] - at.shift_u - b.u0) +
                                        std::abs(c.uv[1] - at.shift_v - b.v0));
    }
    // The pieces cover T's simplex up to a few ulps of lambda, and their
    // (u,v) corners and local parameters are rounded within a few ulps of
    // the parameters' magnitude (the restriction's moved corners among
    // them: triangle_restriction.h), where a patch's continuation and its
    // neighbour differ by less than twice the gradient times the distance;
    // the mesh values at the pieces' corners are rounded sums of Q.
    const double r_uv = 64 * kU * (far + (hi[0] - lo[0]) + (hi[1] - lo[1]) + local);
    const double slack = 4 * gradient * r_uv + 64 * kU * qmax;
    // A piece whose bound is at most this keeps the whole at most cutoff.
    const double piece_cutoff = cutoff / (1 + 4e-12) - slack;
    double worst = 0;
    for (size_t k = 0; k < pieces.size(); ++k) {
        const Placed& at = placed[k];
        worst = std::max(worst, piece_bound(pieces[k], patches_[at.patch], at.shift_u, at.shift_v,
                                            Q, piece_cutoff));
        if (!(worst < kInf)) return kInf;
    }
    return (worst + slack) * (1 + 1e-12);
}

} // namespace seamless
