// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/interval/interval.h>
#include <seamless/spline/enclosure/triangle_restriction.h>
#include <seamless/spline/knot_insertion.h>
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
