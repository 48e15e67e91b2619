// SPDX-License-Identifier: MIT
#include <seamless/tessellate/error_bound.h>
#include <seamless/tessellate/planarity.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace seamless {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Bounds over [0,1]^2 of S' = S - c and its first and second partial
// derivatives, measured by `mag` (the Euclidean norm, or |n . v| for a unit n).
// X' = X - W c is the homogeneous form of S'; its derivatives' Bernstein
// coefficients are differences of the control net, bounded by their largest
// magnitude (convex hull property); the quotient rule with W >= wlo > 0 gives
//   S_s  = (X'_s - S' W_s) / W,
//   S_ss = (X'_ss - 2 S_s W_s - S' W_ss) / W,
//   S_st = (X'_st - S_s W_t - S_t W_s - S' W_st) / W.
struct DerivativeBounds {
    double A = 0, B = 0, C = 0; // |S_ss|, |S_st|, |S_tt|
};

struct Net {
    int p = 0, q = 0;
    std::array<Vec3, BezierPatch::kMaxOrder * BezierPatch::kMaxOrder> x{}; // w (P - c)
    std::array<double, BezierPatch::kMaxOrder * BezierPatch::kMaxOrder> w{};
    std::array<Vec3, BezierPatch::kMaxOrder * BezierPatch::kMaxOrder> d{}; // P - c
    double wlo = 1;
    const Vec3& X(int i, int j) const { return x[i * BezierPatch::kMaxOrder + j]; }
    double W(int i, int j) const { return w[i * BezierPatch::kMaxOrder + j]; }
    const Vec3& D(int i, int j) const { return d[i * BezierPatch::kMaxOrder + j]; }
};

Net make_net(const BezierPatch& b, Vec3 c) {
    Net n;
    n.p = b.p;
    n.q = b.q;
    n.wlo = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= b.p; ++i)
        for (int j = 0; j <= b.q; ++j) {
            const HPoint& h = b.at(i, j);
            const int k = i * BezierPatch::kMaxOrder + j;
            n.x[k] = h.xyz() - h.w * c;
            n.w[k] = h.w;
            n.d[k] = h.point() - c;
            n.wlo = std::min(n.wlo, h.w);
        }
    assert(n.wlo > 0);
    return n;
}

template <class Mag> DerivativeBounds derivative_bounds(const Net& n, Mag&& mag) {
    const int p = n.p, q = n.q;
    double P0 = 0, Xs = 0, Xt = 0, Xss = 0, Xst = 0, Xtt = 0;
    double Ws = 0, Wt = 0, Wss = 0, Wst = 0, Wtt = 0;
    for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j) {
            P0 = std::max(P0, mag(n.D(i, j)));
            if (i < p) {
                Xs = std::max(Xs, mag(n.X(i + 1, j) - n.X(i, j)));
                Ws = std::max(Ws, std::abs(n.W(i + 1, j) - n.W(i, j)));
            }
            if (j < q) {
                Xt = std::max(Xt, mag(n.X(i, j + 1) - n.X(i, j)));
                Wt = std::max(Wt, std::abs(n.W(i, j + 1) - n.W(i, j)));
            }
            if (i + 1 < p) {
                Xss = std::max(Xss, mag(n.X(i + 2, j) - 2 * n.X(i + 1, j) + n.X(i, j)));
                Wss = std::max(Wss, std::abs(n.W(i + 2, j) - 2 * n.W(i + 1, j) + n.W(i, j)));
            }
            if (j + 1 < q) {
                Xtt = std::max(Xtt, mag(n.X(i, j + 2) - 2 * n.X(i, j + 1) + n.X(i, j)));
                Wtt = std::max(Wtt, std::abs(n.W(i, j + 2) - 2 * n.W(i, j + 1) + n.W(i, j)));
            }
            if (i < p && j < q) {
                Xst = std::max(Xst,
                               mag(n.X(i + 1, j + 1) - n.X(i + 1, j) - n.X(i, j + 1) + n.X(i, j)));
                Wst = std::max(Wst, std::abs(n.W(i + 1, j + 1) - n.W(i + 1, j) - n.W(i, j + 1) +
                                             n.W(i, j)));
            }
        }
    Xs *= p, Ws *= p, Xt *= q, Wt *= q;
    Xss *= p * (p - 1), Wss *= p * (p - 1);
    Xtt *= q * (q - 1), Wtt *= q * (q - 1);
    Xst *= p * q, Wst *= p * q;
    const double Ps = (Xs + P0 * Ws) / n.wlo, Pt = (Xt + P0 * Wt) / n.wlo;
    DerivativeBounds r;
    r.A = (Xss + 2 * Ps * Ws + P0 * Wss) / n.wlo;
    r.B = (Xst + Ps * Wt + Pt * Ws + P0 * Wst) / n.wlo;
    r.C = (Xtt + 2 * Pt * Wt + P0 * Wtt) / n.wlo;
    // Rounding of the differences and products: relative, a few ulps each.
    const double inflate = 1 + 64 * kEps;
    r.A *= inflate, r.B *= inflate, r.C *= inflate;
    return r;
}

double remainder(const DerivativeBounds& d, double ds, double dt) {
    return (d.A * ds * ds + 2 * d.B * ds * dt + d.C * dt * dt) / 8;
}

struct Param {
    double s = 0, t = 0;
};

// One Gauss-Newton step from u toward the foot of x on S; returns the new
// parameter, clamped to [0,1]^2.
Param foot(const BezierPatch& b, Vec3 x, Param u) {
    const SurfacePoint sp = evaluate(b, u.s, u.t);
    const Vec3 r = x - sp.point;
    const double a11 = dot(sp.du, sp.du), a22 = dot(sp.dv, sp.dv), a12 = dot(sp.du, sp.dv);
    const double reg = 1e-12 * (a11 + a22);
    const double g1 = dot(sp.du, r), g2 = dot(sp.dv, r);
    const double det = (a11 + reg) * (a22 + reg) - a12 * a12;
    if (!(det > 0) || !std::isfinite(det)) return u;
    const double ds = ((a22 + reg) * g1 - a12 * g2) / det, dt = ((a11 + reg) * g2 - a12 * g1) / det;
    if (!std::isfinite(ds) || !std::isfinite(dt)) return u;
    return {std::clamp(u.s + ds, 0.0, 1.0), std::clamp(u.t + dt, 0.0, 1.0)};
}

// Same along side k of [0,1]^2 (corner k to corner k+1), parameter tau in [lo, 1].
double foot_on_side(const BezierPatch& b, Vec3 x, Param c0, Param c1, double tau, double lo) {
    const Param u{c0.s + tau * (c1.s - c0.s), c0.t + tau * (c1.t - c0.t)};
    const SurfacePoint sp = evaluate(b, u.s, u.t);
    const Vec3 d = (c1.s - c0.s) * sp.du + (c1.t - c0.t) * sp.dv;
    const double dd = dot(d, d);
    if (!(dd > 0) || !std::isfinite(dd)) return std::clamp(tau, lo, 1.0);
    const double step = dot(d, x - sp.point) / dd;
    if (!std::isfinite(step)) return std::clamp(tau, lo, 1.0);
    return std::clamp(tau + step, lo, 1.0);
}

constexpr Param kCorner[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
constexpr Param kCentre{0.5, 0.5};

// A refined vertex: its parameter under phi and g = S(phi(w)) - F(w).
struct Node {
    Param u;
    Vec3 g;
};

} // namespace

double fan_bound(const BezierPatch& b, Vec3 centre, const std::array<Vec3, 4>& V, double target) {
    const Net net = make_net(b, centre);
    const DerivativeBounds full = derivative_bounds(net, [](Vec3 v) { return norm(v); });

    // Unit normals of the fan triangles (any unit vector keeps the bound valid:
    // degenerate triangles borrow the subpatch's corner normal).
    std::array<Vec3, 4> n{};
    const Vec3 diag = cross(V[2] - V[0], V[3] - V[1]);
    for (int k = 0; k < 4; ++k) {
        const Vec3 c = cross(V[k] - centre, V[(k + 1) % 4] - centre);
        const double len = norm(c);
        n[k] = len > 1e-300 && std::isfinite(len) ? c / len : normalize(diag);
    }
    std::array<DerivativeBounds, 4> nb{};
    for (int k = 0; k < 4; ++k)
        nb[k] = norm(n[k]) > 0 ? derivative_bounds(net, [&](Vec3 v) { return std::abs(dot(v, n[k])); })
                               : full;

    // m: the tangential remainder of an unrefined fan triangle (extents 1 x 1/2)
    // against its normal remainder (about the geometric deviation) or the target.
    double R1 = 0, Rn1 = 0;
    for (int k = 0; k < 4; ++k) {
        const double ds = k % 2 == 0 ? 1.0 : 0.5, dt = k % 2 == 0 ? 0.5 : 1.0;
        R1 = std::max(R1, remainder(full, ds, dt));
        Rn1 = std::max(Rn1, remainder(nb[k], ds, dt));
    }
    const double want = std::max(0.4 * Rn1, 0.2 * target);
    int m = 1;
    if (R1 > 0)
        m = want > 0 ? static_cast<int>(std::ceil(std::sqrt(R1 / want))) : kMaxFanRefinement;
    m = std::clamp(m, 1, kMaxFanRefinement);

    // phi on the radial edges (centre to corner k), shared by two fan triangles.
    constexpr int K = kMaxFanRefinement + 1;
    Node radial[4][K];
    for (int k = 0; k < 4; ++k)
        for (int a = 0; a <= m; ++a) {
            const double f = static_cast<double>(a) / m;
            const Param w{kCentre.s + f * (kCorner[k].s - kCentre.s),
                          kCentre.t + f * (kCorner[k].t - kCentre.t)};
            const Vec3 x = centre + f * (V[k] - centre);
            Param u = w;
            if (a == 0)
                u = kCentre;
            else if (a == m)
                u = kCorner[k];
            else
                u = foot(b, x, w);
            radial[k][a] = {u, evaluate(b, u.s, u.t).point - x};
        }

    double bound = 0;
    Node grid[K][K]; // grid[a][b]: centre + a/m (V[k] - centre) + b/m (V[k+1] - centre)
    for (int k = 0; k < 4; ++k) {
        const int k1 = (k + 1) % 4;
        for (int a = 0; a <= m; ++a) grid[a][0] = radial[k][a];
        for (int c = 0; c <= m; ++c) grid[0][c] = radial[k1][c];
        // Side k: a + c = m, tau = c / m from corner k; monotone in tau.
        double lo = 0;
        for (int c = 1; c < m; ++c) {
            const int a = m - c;
            const double tau = static_cast<double>(c) / m;
            const Vec3 x = V[k] + tau * (V[k1] - V[k]);
            lo = foot_on_side(b, x, kCorner[k], kCorner[k1], tau, lo);
            const Param u{kCorner[k].s + lo * (kCorner[k1].s - kCorner[k].s),
                          kCorner[k].t + lo * (kCorner[k1].t - kCorner[k].t)};
            grid[a][c] = {u, evaluate(b, u.s, u.t).point - x};
        }
        // Interior.
        for (int a = 1; a < m; ++a)
            for (int c = 1; a + c < m; ++c) {
                const double fa = static_cast<double>(a) / m, fc = static_cast<double>(c) / m;
                const Param w{kCentre.s + fa * (kCorner[k].s - kCentre.s) +
                                  fc * (kCorner[k1].s - kCentre.s),
                              kCentre.t + fa * (kCorner[k].t - kCentre.t) +
                                  fc * (kCorner[k1].t - kCentre.t)};
                const Vec3 x = centre + fa * (V[k] - centre) + fc * (V[k1] - centre);
                const Param u = foot(b, x, w);
                grid[a][c] = {u, evaluate(b, u.s, u.t).point - x};
            }
        // Refined triangles: up (a,c),(a+1,c),(a,c+1); down (a+1,c),(a+1,c+1),(a,c+1).
        auto tri = [&](const Node& p0, const Node& p1, const Node& p2) {
            double gn = 0, gt = 0;
            for (const Node* q : {&p0, &p1, &p2}) {
                const double dn = dot(q->g, n[k]);
                gn = std::max(gn, std::abs(dn));
                gt = std::max(gt, norm(q->g - dn * n[k]));
            }
            const double ds = std::max({p0.u.s, p1.u.s, p2.u.s}) - std::min({p0.u.s, p1.u.s, p2.u.s});
            const double dt = std::max({p0.u.t, p1.u.t, p2.u.t}) - std::min({p0.u.t, p1.u.t, p2.u.t});
            const double en = gn + remainder(nb[k], ds, dt), et = gt + remainder(full, ds, dt);
            bound = std::max(bound, std::sqrt(en * en + et * et));
        };
        for (int a = 0; a < m; ++a)
            for (int c = 0; a + c < m; ++c) {
                tri(grid[a][c], grid[a + 1][c], grid[a][c + 1]);
                if (a + c + 2 <= m) tri(grid[a + 1][c], grid[a + 1][c + 1], grid[a][c + 1]);
            }
    }
    // Relative rounding of the sums above.
    return bound * (1 + 64 * kEps);
}

double rounding_allowance(int depth, double scale) {
    return (8.0 * (depth + 8)) * kEps * scale;
}

BezierPatch extract_subpatch(const BezierPatch& patch, const ParamRect& r) {
    BezierPatch cur = patch, lo, hi;
    const double s0 = param_of(r.s0), s1 = param_of(r.s1);
    const double t0 = param_of(r.t0), t1 = param_of(r.t1);
    if (s0 > 0) {
        split_u(cur, s0, lo, hi);
        cur = hi;
    }
    if (s1 < 1) {
        split_u(cur, (s1 - s0) / (1 - s0), lo, hi);
        cur = lo;
    }
    if (t0 > 0) {
        split_v(cur, t0, lo, hi);
        cur = hi;
    }
    if (t1 < 1) {
        split_v(cur, (t1 - t0) / (1 - t0), lo, hi);
        cur = lo;
    }
    return cur;
}

double certified_fan_bound(const BezierPatch& patch, const Subpatch& sp, Vec3 centre,
                           std::span<const FanVertex> ring, double scale) {
    std::array<Vec3, 4> V{};
    std::array<int, 4> at{};
    int corner = 0;
    for (size_t i = 0; i < ring.size(); ++i) {
        const FanVertex& v = ring[i];
        if ((v.s == 0 || v.s == 1) && (v.t == 0 || v.t == 1)) {
            assert(corner < 4);
            V[corner] = v.position;
            at[corner] = static_cast<int>(i);
            ++corner;
        }
    }
    assert(corner == 4);
    // Moving a vertex by d moves the union of its triangles by at most d.
    double shift = distance(centre, sp.centre);
    for (int k = 0; k < 4; ++k) shift = std::max(shift, distance(V[k], sp.corners[k]));
    double base = sp.fan_error + shift;
    int depth = sp.depth;
    if (shift > 0.05 * sp.fan_error) {
        // Neighbours moved a corner (onto their straight edge): recompute.
        const BezierPatch sub = extract_subpatch(patch, sp.rect);
        base = std::min(base, fan_bound(sub, centre, V));
        depth += 4 * BezierPatch::kMaxOrder;
    }
    // Extra vertices on side k: their distance to the segment V[k] V[k+1].
    double off = 0;
    for (int k = 0; k < 4; ++k) {
        const int end = k < 3 ? at[k + 1] : static_cast<int>(ring.size());
        for (int i = at[k] + 1; i < end; ++i)
            off = std::max(off, point_segment_distance(ring[i].position, V[k], V[(k + 1) % 4]));
    }
    return (base + off) * (1 + 64 * kEps) + rounding_allowance(depth + 4 * BezierPatch::kMaxOrder, scale);
}

} // namespace seamless
