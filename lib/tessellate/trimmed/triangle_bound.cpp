// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/interval/interval.h>
#include <seamless/spline/knot_insertion.h>
#include <seamless/tessellate/bounds/error_bound.h>
#include <seamless/tessellate/trimmed/triangle_bound.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<double> distinct_knots(const std::vector<double>& U, double lo, double hi) {
    std::vector<double> out;
    for (double t : U)
        if (t >= lo && t <= hi && (out.empty() || out.back() != t)) out.push_back(t);
    return out;
}

int multiplicity(const std::vector<double>& U, double t) {
    return static_cast<int>(std::count(U.begin(), U.end(), t));
}

// Bound of the jump of S's first derivative across the line where patch L
// ends and patch R begins (direction u: L's row p is R's row 0; v: columns),
// from the Bernstein coefficients of the jump of the homogeneous derivative:
// dS = (dX - S dW) / W, the jump of X and W zero (the row is shared).
double derivative_jump(const BezierPatch& L, const BezierPatch& R, Direction d) {
    const bool u = d == Direction::u;
    const int n = u ? L.p : L.q, m = u ? L.q : L.p;
    const double hl = u ? L.u1 - L.u0 : L.v1 - L.v0, hr = u ? R.u1 - R.u0 : R.v1 - R.v0;
    auto at = [u](const BezierPatch& b, int i, int j) { return u ? b.at(i, j) : b.at(j, i); };
    const Vec3 c = at(L, n, 0).point();
    double jump = 0, spread = 0, dw = 0, wmin = kInf, size = 0;
    for (int j = 0; j <= m; ++j) {
        const HPoint x = at(L, n, j);
        if (!(x.xyz() == at(R, 0, j).xyz() && x.w == at(R, 0, j).w)) return kInf; // not C0
        const HPoint left = (n / hl) * (x - at(L, n - 1, j));
        const HPoint right = (n / hr) * (at(R, 1, j) - x);
        const HPoint delta = right - left;
        jump = std::max(jump, norm(delta.xyz() - delta.w * c));
        spread = std::max(spread, norm(x.point() - c));
        dw = std::max(dw, std::abs(delta.w));
        wmin = std::min(wmin, x.w);
        size = std::max(size, norm(left.xyz()) + norm(right.xyz()) +
                                  (std::abs(left.w) + std::abs(right.w)) * norm(c));
    }
    // A few roundings per difference, each within eps of the terms' size.
    return (jump + spread * dw + 16 * kEps * size) / wmin * (1 + 1e-12);
}

// Bounds of |S_ss|, |S_st|, |S_tt| over b's local [0,1]^2: the Bernstein
// coefficients of X and W and of their partial derivatives (differences of
// the net, in interval arithmetic) enclose them over the square, and the
// quotient rule runs on those enclosures
//   S = X / W, S_s = (X_s - S W_s) / W, S_t alike,
//   S_ss = (X_ss - 2 S_s W_s - S W_ss) / W,
//   S_st = (X_st - S_s W_t - S_t W_s - S W_st) / W, S_tt alike.
// Over a small box the enclosures are narrow, so X_st and S_t W_s, which
// cancel where only the weights vary (a cylinder's rulings), nearly cancel
// here too; a bound from the coefficients' magnitudes alone would not.
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
    const double up = 1 + 8 * kEps;
    return {std::sqrt(ss * up) * up, std::sqrt(st * up) * up, std::sqrt(tt * up) * up};
}

// The largest of sum lambda_k |x_k - x|^2 over the triangle (header).
double rho_squared(const std::array<UV, 3>& x) {
    double l2[3];
    for (int k = 0; k < 3; ++k) {
        const double du = x[(k + 1) % 3][0] - x[(k + 2) % 3][0];
        const double dv = x[(k + 1) % 3][1] - x[(k + 2) % 3][1];
        l2[k] = du * du + dv * dv; // the side opposite corner k
    }
    const double longest = std::max({l2[0], l2[1], l2[2]});
    const double others = l2[0] + l2[1] + l2[2] - longest;
    if (longest >= others) return longest / 4 * (1 + 1e-12); // right or obtuse
    // R^2 = a^2 b^2 c^2 / (16 area^2), 16 area^2 = 2 sum a^2 b^2 - sum a^4.
    const double a2 = l2[0], b2 = l2[1], c2 = l2[2];
    const double area16 = 2 * (a2 * b2 + b2 * c2 + c2 * a2) - (a2 * a2 + b2 * b2 + c2 * c2);
    const double r2 = area16 > 0 ? a2 * b2 * c2 / area16 : kInf;
    // Acute: R^2 <= l^2 / 3, which also covers a rounded area.
    return std::min(r2 * (1 + 1e-9), longest / 3 * (1 + 1e-12));
}

} // namespace

TriangleBound::TriangleBound(const BSplineSurface& s)
    : patches_(bezier_patches(s, -1)), surface_(s) {
    u_.at = distinct_knots(s.knots_u, s.u_min(), s.u_max());
    v_.at = distinct_knots(s.knots_v, s.v_min(), s.v_max());
    for (Vec3 p : s.points)
        magnitude_ = std::max({magnitude_, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    find_jumps(s);
}

void TriangleBound::find_jumps(const BSplineSurface& s) {
    const int nu = static_cast<int>(u_.at.size()) - 1, nv = static_cast<int>(v_.at.size()) - 1;
    SEAMLESS_CHECK(static_cast<int>(patches_.size()) == nu * nv,
                   "one Bezier patch per pair of knot spans");
    auto patch = [&](int iu, int iv) -> const BezierPatch& { return patches_[iu * nv + iv]; };
    u_.jump.assign(std::max(nu - 1, 0), 0.0);
    for (int i = 1; i < nu; ++i) {
        // Multiplicity below the degree: the basis is C1 there, no jump.
        if (multiplicity(s.knots_u, u_.at[i]) < s.degree_u) continue;
        for (int iv = 0; iv < nv; ++iv)
            u_.jump[i - 1] = std::max(
                u_.jump[i - 1], derivative_jump(patch(i - 1, iv), patch(i, iv), Direction::u));
    }
    v_.jump.assign(std::max(nv - 1, 0), 0.0);
    for (int j = 1; j < nv; ++j) {
        if (multiplicity(s.knots_v, v_.at[j]) < s.degree_v) continue;
        for (int iu = 0; iu < nu; ++iu)
            v_.jump[j - 1] = std::max(
                v_.jump[j - 1], derivative_jump(patch(iu, j - 1), patch(iu, j), Direction::v));
    }
}

double TriangleBound::jumps_inside(const Breaks& b, double lo, double hi) const {
    double sum = 0;
    for (size_t i = 1; i + 1 < b.at.size(); ++i)
        if (b.at[i] > lo && b.at[i] < hi) sum += b.jump[i - 1];
    return sum;
}

std::array<double, 3> TriangleBound::second_derivatives(double u0, double u1, double v0,
                                                        double v1) const {
    std::array<double, 3> d{0, 0, 0};
    for (const BezierPatch& p : patches_) {
        const double a = std::max(u0, p.u0), b = std::min(u1, p.u1);
        const double c = std::max(v0, p.v0), e = std::min(v1, p.v1);
        if (!(a < b && c < e)) continue; // no area in common: the neighbours bound it
        double s0 = (a - p.u0) / (p.u1 - p.u0), s1 = (b - p.u0) / (p.u1 - p.u0);
        double t0 = (c - p.v0) / (p.v1 - p.v0), t1 = (e - p.v0) / (p.v1 - p.v0);
        // A sliver of a patch would divide the rounding of its differences by
        // its squared width: take at least an eighth of the patch (a superset
        // of the box, so still a bound).
        auto widen = [](double& lo, double& hi) {
            if (hi - lo >= 0.125) return;
            const double mid = (lo + hi) / 2;
            lo = std::clamp(mid - 0.0625, 0.0, 0.875);
            hi = lo + 0.125;
        };
        widen(s0, s1);
        widen(t0, t1);
        const auto [A, B, C] = second_derivative_ranges(extract_box(p, s0, s1, t0, t1));
        const double wu = (s1 - s0) * (p.u1 - p.u0), wv = (t1 - t0) * (p.v1 - p.v0);
        d[0] = std::max(d[0], A / (wu * wu));
        d[1] = std::max(d[1], B / (wu * wv));
        d[2] = std::max(d[2], C / (wv * wv));
    }
    for (double& x : d) x *= 1 + 1e-12;
    return d;
}

double TriangleBound::operator()(const std::array<UV, 3>& uv, const std::array<Vec3, 3>& Q) const {
    double u0 = kInf, u1 = -kInf, v0 = kInf, v1 = -kInf;
    for (const UV& x : uv) {
        u0 = std::min(u0, x[0]), u1 = std::max(u1, x[0]);
        v0 = std::min(v0, x[1]), v1 = std::max(v1, x[1]);
    }
    // A corner outside the surface's domain (a pcurve past the surface's
    // edge, which the tessellator extends) has no surface point to bound
    // against: not certified.
    if (u0 < surface_.u_min() || u1 > surface_.u_max() || v0 < surface_.v_min() ||
        v1 > surface_.v_max())
        return kInf;
    double corner = 0, wmax = 0, wmin = kInf;
    for (double w : surface_.weights) wmax = std::max(wmax, w), wmin = std::min(wmin, w);
    const double wratio = surface_.weights.empty() ? 1 : wmax / wmin;
    for (int k = 0; k < 3; ++k)
        corner = std::max(corner, distance(evaluate(surface_, uv[k][0], uv[k][1]).point, Q[k]));
    // de Boor's evaluation: a few roundings per level, each within eps of
    // the control points' magnitude (times the weights' spread).
    corner += 16.0 * (surface_.degree_u + surface_.degree_v + 2) * kEps * magnitude_ * wratio;
    // The extracted subpatches (de Casteljau in doubles) are polynomials
    // within a few ulps of the surface: their interpolation error differs
    // from the surface's by at most twice that.
    corner += 2 * rounding_allowance(16, magnitude_) * wratio;
    // Plain names, not a structured binding: the lambda below captures them.
    const std::array<double, 3> d2 = second_derivatives(u0, u1, v0, v1);
    const double A = d2[0], B = d2[1], C = d2[2];
    const double Ju = jumps_inside(u_, u0, u1), Jv = jumps_inside(v_, v0, v1);
    if (!std::isfinite(A + B + C + Ju + Jv)) return kInf;
    // In the scaling u' = u alpha, v' = v beta: S_u'u' = S_uu / alpha^2, ...
    auto bound_in = [&](double alpha, double beta) {
        const double a = A / (alpha * alpha), b = B / (alpha * beta), c = C / (beta * beta);
        const double M = (a + c) / 2 + std::sqrt((a - c) * (a - c) / 4 + b * b);
        std::array<UV, 3> x;
        // Differences from one corner: far from the origin the coordinates'
        // own magnitude would round them away.
        for (int k = 0; k < 3; ++k)
            x[k] = {(uv[k][0] - uv[0][0]) * alpha, (uv[k][1] - uv[0][1]) * beta};
        const double r2 = rho_squared(x);
        return M * r2 / 2 + (Ju / alpha + Jv / beta) * std::sqrt(r2);
    };
    double best = bound_in(1, 1);
    const double top = std::max(A, C);
    if (top > 0) {
        const double alpha = std::sqrt(std::max(A, 1e-6 * top)),
                     beta = std::sqrt(std::max(C, 1e-6 * top));
        best = std::min(best, bound_in(alpha, beta));
    }
    return (best + corner) * (1 + 1e-12);
}

} // namespace seamless
