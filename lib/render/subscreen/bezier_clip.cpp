// SPDX-License-Identifier: MIT
// Theorem 10's narrowing on a subpatch by Bezier clipping (bezier_clip.h).
#include <seamless/render/subscreen/bezier_clip.h>

#include <seamless/interval/lanes.h>

#include <cmath>
#include <limits>

namespace seamless {

namespace {

// The zeros' range along one direction: the hull of the points (i / n, y),
// y in C_i = hull of column i, meets the axis in [lo, hi] (outward), found
// from the crossings of the segments between points on opposite sides.
//
// A crossing x = (i + (j - i) y_i / (y_i - y_j)) / n is computed in doubles:
// f = y_i / (y_i - y_j) in (0, 1) with absolute error below 3u (u = 2^-53),
// (j - i) f, the sum with i and the product with fl(1 / n) add at most a few
// roundings of numbers below n <= 9, so |error| < (6n + 10) u < 1e-14; the
// bounds are widened by 1e-13 and clamped to [i / n, j / n] (enclosed by
// interval division), where the crossing lies. Where y_i - y_j could be subnormal (relative bounds
// fail) or overflows (outside the scene limits, docs/formats.md) the whole
// [i / n, j / n] is taken.
// The enclosures of i / n (interval division), for every degree n, formed once
// rather than on every clip.
struct Abscissae {
    double lo[BezierPatch::kMaxOrder][BezierPatch::kMaxOrder];
    double hi[BezierPatch::kMaxOrder][BezierPatch::kMaxOrder];
    Abscissae() {
        for (int n = 1; n < BezierPatch::kMaxOrder; ++n)
            for (int i = 0; i <= n; ++i) {
                const Interval x =
                    Interval(static_cast<double>(i)) / Interval(static_cast<double>(n));
                lo[n][i] = x.lo();
                hi[n][i] = x.hi();
            }
    }
};
const Abscissae& abscissae() {
    static const Abscissae table;
    return table;
}

// Degree: an int or a std::integral_constant (with_degree, subpatch.h).
template <class Degree> Interval clip_columns(const Interval* C, Degree n) {
    bool above = true, below = true;
    for (int i = 0; i <= n; ++i) {
        above = above && C[i].lo() > 0;
        below = below && C[i].hi() < 0;
    }
    if (above || below) return Interval::empty();
    // Both end columns hold 0: the points (0, 0) and (1, 0) are in the hull,
    // which meets the axis in all of [0, 1] (the loop below would add the
    // enclosures of 0 / n and n / n, which [0, 1] clamps to 0 and 1).
    if (n == 0 || (C[0].contains(0.0) && C[n].contains(0.0))) return {0.0, 1.0};
    const double inv = 1.0 / n;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    auto add = [&](double a, double b) {
        lo = std::min(lo, a);
        hi = std::max(hi, b);
    };
    const double* x_lo = abscissae().lo[n]; // i / n, enclosed
    const double* x_hi = abscissae().hi[n];
    for (int i = 0; i <= n; ++i) {
        const double xi_lo = x_lo[i], xi_hi = x_hi[i];
        if (C[i].contains(0.0)) add(xi_lo, xi_hi);
        for (int j = i + 1; j <= n; ++j) {
            const double xj_hi = x_hi[j];
            for (double yi : {C[i].lo(), C[i].hi()})
                for (double yj : {C[j].lo(), C[j].hi()}) {
                    if (!((yi > 0 && yj < 0) || (yi < 0 && yj > 0))) continue;
                    const double d = yi - yj;
                    if (!(std::abs(d) > 0x1p-1000 && std::abs(d) < 0x1p1000)) {
                        add(xi_lo, xj_hi);
                        continue;
                    }
                    const double x = (i + (j - i) * (yi / d)) * inv;
                    add(std::max(xi_lo, x - 1e-13), std::min(xj_hi, x + 1e-13));
                }
        }
    }
    return intersect(Interval(lo, hi), Interval(0.0, 1.0));
}

// Bernstein coefficient (i, j) of G_k = X_k - e Z (e = a for k = 0, b for k = 1).
Interval g_at(const Interval* c, SubpatchShape sh, Interval e, int k, int i, int j) {
    return c[sh.index(k, i, j)] - e * c[sh.index(2, i, j)];
}

// The lane forms of coefficient_hulls and difference_ranges (lanes.h): the
// same operations in the same order on pairs (-lo, hi), so the same bits.
void coefficient_hulls_lanes(const Interval* c, SubpatchShape sh, Interval e, int k, Interval* col,
                             Interval* row) {
    using namespace lanes;
    constexpr int K = BezierPatch::kMaxOrder;
    const Factor f(e);
    Lanes cl[K], rl[K];
    for (int i = 0; i <= sh.p; ++i) cl[i] = empty();
    for (int j = 0; j <= sh.q; ++j) rl[j] = empty();
    const Interval* x = c + sh.index(k, 0, 0);
    const Interval* z = c + sh.index(2, 0, 0);
    for (int i = 0, ij = 0; i <= sh.p; ++i)
        for (int j = 0; j <= sh.q; ++j, ++ij) {
            const Lanes g = sub(load(x[ij]), mul(f, load(z[ij])));
            cl[i] = hull(cl[i], g);
            rl[j] = hull(rl[j], g);
        }
    for (int i = 0; i <= sh.p; ++i) col[i] = store(cl[i]);
    for (int j = 0; j <= sh.q; ++j) row[j] = store(rl[j]);
}

// difference_ranges_lanes for G_0 (factor a) and G_1 (factor b) in one walk:
// the z differences formed once for both (the same operations on the same
// operands as two calls, so the same bits).
void difference_pair_lanes(const Interval* c, SubpatchShape sh, Interval a, Interval b,
                           IMat<2>& D) {
    using namespace lanes;
    const Factor fa(a), fb(b);
    const Lanes none = empty(), zero = load(Interval(0.0));
    Lanes u0 = sh.p > 0 ? none : zero, u1 = u0;
    Lanes v0 = sh.q > 0 ? none : zero, v1 = v0;
    const Interval* x = c + sh.index(0, 0, 0);
    const Interval* y = c + sh.index(1, 0, 0);
    const Interval* z = c + sh.index(2, 0, 0);
    const int row = sh.q + 1;
    for (int i = 0, ij = 0; i <= sh.p; ++i)
        for (int j = 0; j <= sh.q; ++j, ++ij) {
            const Lanes x0 = load(x[ij]), y0 = load(y[ij]), z0 = load(z[ij]);
            if (i < sh.p) {
                const Lanes dz = sub(load(z[ij + row]), z0);
                u0 = hull(u0, sub(sub(load(x[ij + row]), x0), mul(fa, dz)));
                u1 = hull(u1, sub(sub(load(y[ij + row]), y0), mul(fb, dz)));
            }
            if (j < sh.q) {
                const Lanes dz = sub(load(z[ij + 1]), z0);
                v0 = hull(v0, sub(sub(load(x[ij + 1]), x0), mul(fa, dz)));
                v1 = hull(v1, sub(sub(load(y[ij + 1]), y0), mul(fb, dz)));
            }
        }
    D(0, 0) = store(u0);
    D(0, 1) = store(v0);
    D(1, 0) = store(u1);
    D(1, 1) = store(v1);
}

void difference_ranges_lanes(const Interval* c, SubpatchShape sh, Interval e, int k, Interval& du,
                             Interval& dv) {
    using namespace lanes;
    const Factor f(e);
    Lanes u = sh.p > 0 ? empty() : load(Interval(0.0));
    Lanes v = sh.q > 0 ? empty() : load(Interval(0.0));
    const Interval* x = c + sh.index(k, 0, 0);
    const Interval* z = c + sh.index(2, 0, 0);
    const int row = sh.q + 1;
    for (int i = 0, ij = 0; i <= sh.p; ++i)
        for (int j = 0; j <= sh.q; ++j, ++ij) {
            const Lanes x0 = load(x[ij]), z0 = load(z[ij]);
            if (i < sh.p)
                u = hull(u, sub(sub(load(x[ij + row]), x0), mul(f, sub(load(z[ij + row]), z0))));
            if (j < sh.q)
                v = hull(v, sub(sub(load(x[ij + 1]), x0), mul(f, sub(load(z[ij + 1]), z0))));
        }
    du = store(u);
    dv = store(v);
}

} // namespace

bool cluster_lanes_apply(const Interval* c, SubpatchShape sh, Interval a, Interval b) {
    // Coefficients and differences below 2^501, factors below 2^500: every
    // product and difference stays below 2^1002, far from overflow.
    const Interval ab[2] = {a, b};
    return lanes::moderate(ab, 2, 0x1p500) &&
           lanes::moderate(c, 3 * (sh.p + 1) * (sh.q + 1), 0x1p500);
}

void coefficient_hulls(const Interval* c, SubpatchShape sh, Interval e, int k, Interval* col,
                       Interval* row, bool lanes) {
    if (lanes) return coefficient_hulls_lanes(c, sh, e, k, col, row);
    for (int i = 0; i <= sh.p; ++i) col[i] = Interval::empty();
    for (int j = 0; j <= sh.q; ++j) row[j] = Interval::empty();
    for (int i = 0; i <= sh.p; ++i)
        for (int j = 0; j <= sh.q; ++j) {
            const Interval g = g_at(c, sh, e, k, i, j);
            col[i] = hull(col[i], g);
            row[j] = hull(row[j], g);
        }
}

void difference_ranges(const Interval* c, SubpatchShape sh, Interval e, int k, Interval& du,
                       Interval& dv, bool lanes) {
    if (lanes) return difference_ranges_lanes(c, sh, e, k, du, dv);
    du = sh.p > 0 ? Interval::empty() : Interval(0.0);
    dv = sh.q > 0 ? Interval::empty() : Interval(0.0);
    for (int i = 0; i <= sh.p; ++i)
        for (int j = 0; j <= sh.q; ++j) {
            if (i < sh.p)
                du = hull(du, (c[sh.index(k, i + 1, j)] - c[sh.index(k, i, j)]) -
                                  e * (c[sh.index(2, i + 1, j)] - c[sh.index(2, i, j)]));
            if (j < sh.q)
                dv = hull(dv, (c[sh.index(k, i, j + 1)] - c[sh.index(k, i, j)]) -
                                  e * (c[sh.index(2, i, j + 1)] - c[sh.index(2, i, j)]));
        }
}

void cluster_differences(const Interval* c, SubpatchShape sh, Interval a, Interval b, IMat<2>& D,
                         bool lanes) {
    if (lanes) return difference_pair_lanes(c, sh, a, b, D);
    for (int k = 0; k < 2; ++k)
        difference_ranges(c, sh, k == 0 ? a : b, k, D(k, 0), D(k, 1), false);
}

IMat<2> subpatch_jacobian(const Interval* c, SubpatchShape sh, const ParamBox& box, Interval a,
                          Interval b) {
    const Interval ws = Interval(box.s.hi()) - Interval(box.s.lo());
    const Interval wt = Interval(box.t.hi()) - Interval(box.t.lo());
    IMat<2> A;
    cluster_differences(c, sh, a, b, A, cluster_lanes_apply(c, sh, a, b));
    for (int k = 0; k < 2; ++k) {
        A(k, 0) = Interval(static_cast<double>(sh.p)) * A(k, 0) / ws;
        A(k, 1) = Interval(static_cast<double>(sh.q)) * A(k, 1) / wt;
    }
    return A;
}

bool clip_cluster(const Interval* c, SubpatchShape sh, Interval a, Interval b, Interval& u,
                  Interval& v, IMat<2>* D) {
    constexpr int K = BezierPatch::kMaxOrder;
    u = Interval(0.0, 1.0);
    v = Interval(0.0, 1.0);
    const bool lanes = cluster_lanes_apply(c, sh, a, b);
    auto clip = [](const Interval* C, int n) {
        return with_degree(n, [&](auto m) { return clip_columns(C, m); });
    };
    for (int k = 0; k < 2; ++k) {
        const Interval e = k == 0 ? a : b;
        Interval col[K], row[K];
        coefficient_hulls(c, sh, e, k, col, row, lanes);
        u = intersect(u, clip(col, sh.p));
        if (u.is_empty()) return false; // no need for the rows' clip
        v = intersect(v, clip(row, sh.q));
        if (v.is_empty()) return false;
    }
    if (D) cluster_differences(c, sh, a, b, *D, lanes);
    return true;
}

Interval edge_range(const Interval* c, SubpatchShape sh, Interval a, Interval b, int k, int dir,
                    bool far) {
    const Interval e = k == 0 ? a : b;
    Interval r = Interval::empty();
    if (dir == 0) {
        const int i = far ? sh.p : 0;
        for (int j = 0; j <= sh.q; ++j) r = hull(r, g_at(c, sh, e, k, i, j));
    } else {
        const int j = far ? sh.q : 0;
        for (int i = 0; i <= sh.p; ++i) r = hull(r, g_at(c, sh, e, k, i, j));
    }
    return r;
}

} // namespace seamless
