// SPDX-License-Identifier: MIT
#include <seamless/spline/enclosure/subpatch.h>

#include <seamless/base/check.h>
#include <seamless/interval/lanes.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless {
namespace {

// De Casteljau steps are convex combinations (1 - u) c_i + u c_{i+1}: each
// coefficient enters once, so widths do not grow from step to step (the form
// c_i + u (c_{i+1} - c_i) would double them at every level).
//
// w c for w >= 0 (the de Casteljau weights): two products instead of the
// sign cases of both factors; the general product where a bound is infinite.
inline Interval weight_times(Interval w, Interval c) {
    const double lo = c.lo() >= 0 ? w.lo() * c.lo() : w.hi() * c.lo();
    const double hi = c.hi() >= 0 ? w.hi() * c.hi() : w.lo() * c.hi();
    if (!(std::abs(lo) <= std::numeric_limits<double>::max() &&
          std::abs(hi) <= std::numeric_limits<double>::max()))
        return w * c;
    return {next_down(lo), next_up(hi)};
}

// One row of n + 1 coefficients with stride `stride`: the left part of a split
// at u (domain [0, u]), in place. After pass k, position i >= k holds
// b_{i-k}^{(k)} of the de Casteljau triangle, so position k keeps b_0^{(k)}.
void left_part(Interval* c, int n, int stride, Interval u) {
    const Interval v = intersect(Interval(1.0) - u, Interval(0.0, 1.0)); // u in [0, 1]
    for (int k = 1; k <= n; ++k)
        for (int i = n; i >= k; --i) {
            Interval& ci = c[i * stride];
            ci = weight_times(v, c[(i - 1) * stride]) + weight_times(u, ci);
        }
}
// The right part of a split at u (domain [u, 1]), in place: position j keeps
// b_j^{(n-j)}.
void right_part(Interval* c, int n, int stride, Interval u) {
    const Interval v = intersect(Interval(1.0) - u, Interval(0.0, 1.0)); // u in [0, 1]
    for (int k = 1; k <= n; ++k)
        for (int i = 0; i <= n - k; ++i) {
            Interval& ci = c[i * stride];
            ci = weight_times(v, ci) + weight_times(u, c[(i + 1) * stride]);
        }
}

// The same two passes on pairs (-lo, hi) of doubles, two lanes at once: with
// the lower bound negated, both bounds round up, and next_down(x) = -next_up(-x)
// makes every result bit for bit that of left_part and right_part above. For
// w >= 0 and a lane x, the product's bound is w.hi x where x > 0, else w.lo x
// (a zero x gives a zero either way, and the outward step ignores the sign of
// zero). Only for finite coefficients below 2^1000 and finite weights in [0,1]:
// then no product or convex combination overflows.
using lanes::Lanes;
using lanes::weight_up;

// The weights 1 - u and u of a de Casteljau pass at u, as lane splats of
// their bounds: formed once per restriction, not per row.
struct PassWeights {
    Lanes vl, vh, ul, uh;
    explicit PassWeights(Interval u) {
        const Interval v = intersect(Interval(1.0) - u, Interval(0.0, 1.0)); // u in [0, 1]
        vl = lanes::splat(v.lo());
        vh = lanes::splat(v.hi());
        ul = lanes::splat(u.lo());
        uh = lanes::splat(u.hi());
    }
};

// Left part at u1 then right part at r of every row of direction dir (either
// pass skipped when its weights are null), as left_part and right_part.
// Degree is an int or a std::integral_constant: a fixed degree unrolls the
// passes and keeps a row in registers (same operations in the same order, so
// the same bits).
template <class Degree>
void restrict_rows_lanes(Interval* c, SubpatchShape sh, int dir, Degree n, const PassWeights* left,
                         const PassWeights* right) {
    using lanes::up;
    const int rows = dir == 0 ? sh.q + 1 : sh.p + 1;
    const int stride = dir == 0 ? sh.q + 1 : 1; // between a row's coefficients
    const int next = dir == 0 ? 1 : sh.q + 1;   // between rows of one coordinate
    const int block = (sh.p + 1) * (sh.q + 1);  // between coordinates
    for (int d = 0; d < sh.dim; ++d)
        for (int r = 0; r < rows; ++r) {
            Interval* row = c + d * block + r * next;
            Lanes x[BezierPatch::kMaxOrder];
            for (int i = 0; i <= n; ++i) x[i] = lanes::load(row[i * stride]);
            if (left) {
                const PassWeights& w = *left;
                for (int k = 1; k <= n; ++k)
                    for (int i = n; i >= k; --i)
                        x[i] = up(weight_up(w.vl, w.vh, x[i - 1]) + weight_up(w.ul, w.uh, x[i]));
            }
            if (right) {
                const PassWeights& w = *right;
                for (int k = 1; k <= n; ++k)
                    for (int i = 0; i <= n - k; ++i)
                        x[i] = up(weight_up(w.vl, w.vh, x[i]) + weight_up(w.ul, w.uh, x[i + 1]));
            }
            for (int i = 0; i <= n; ++i) row[i * stride] = lanes::store(x[i]);
        }
}

// Both parts of a split at u of every row of direction dir from one de
// Casteljau triangle: b_0^(k) go to lo (position k), b_{n-k}^(k) to hi
// (position n - k). The left and right passes above form every b_j^(k) as
// v b_j^(k-1) + u b_{j+1}^(k-1) alike, so these are their bits.
template <class Degree>
void split_rows_lanes(const Interval* c, SubpatchShape sh, int dir, Degree n, const PassWeights& w,
                      Interval* lo, Interval* hi) {
    using lanes::up;
    const int rows = dir == 0 ? sh.q + 1 : sh.p + 1;
    const int stride = dir == 0 ? sh.q + 1 : 1;
    const int next = dir == 0 ? 1 : sh.q + 1;
    const int block = (sh.p + 1) * (sh.q + 1);
    for (int d = 0; d < sh.dim; ++d)
        for (int r = 0; r < rows; ++r) {
            const int at = d * block + r * next;
            Lanes x[BezierPatch::kMaxOrder];
            for (int i = 0; i <= n; ++i) x[i] = lanes::load(c[at + i * stride]);
            lo[at] = c[at];
            hi[at + n * stride] = c[at + n * stride];
            for (int k = 1; k <= n; ++k) {
                for (int i = 0; i <= n - k; ++i)
                    x[i] = up(weight_up(w.vl, w.vh, x[i]) + weight_up(w.ul, w.uh, x[i + 1]));
                lo[at + k * stride] = lanes::store(x[0]);
                hi[at + (n - k) * stride] = lanes::store(x[n - k]);
            }
        }
}

// Calls f(row pointer, n, stride) for every row of direction dir.
template <class F> void for_rows(Interval* c, SubpatchShape sh, int dir, F f) {
    for (int d = 0; d < sh.dim; ++d) {
        if (dir == 0) {
            for (int j = 0; j <= sh.q; ++j) f(c + sh.index(d, 0, j), sh.p, sh.q + 1);
        } else {
            for (int i = 0; i <= sh.p; ++i) f(c + sh.index(d, i, 0), sh.q, 1);
        }
    }
}

} // namespace

SubpatchShape subpatch_shape(const BezierPatch& b) {
    bool rational = b.rational;
    for (int i = 0; i <= b.p && !rational; ++i)
        for (int j = 0; j <= b.q; ++j) rational = rational || b.at(i, j).w != 1;
    return {b.p, b.q, rational ? 4 : 3};
}

void control_coefficients(const BezierPatch& b, SubpatchShape sh, Interval* out) {
    for (int d = 0; d < sh.dim; ++d)
        for (int i = 0; i <= sh.p; ++i)
            for (int j = 0; j <= sh.q; ++j) out[sh.index(d, i, j)] = Interval(b.at(i, j)[d]);
}

void restrict_subpatch(Interval* c, SubpatchShape sh, int dir, Interval u0, Interval u1) {
    u0 = intersect(u0, Interval(0.0, 1.0)); // the exact ends lie in [0, 1]
    u1 = intersect(u1, Interval(0.0, 1.0));
    SEAMLESS_CHECK(!u0.is_empty() && !u1.is_empty(), "both ends meet [0, 1]");
    const bool cut_hi = !(u1.is_thin() && u1.lo() == 1);
    const bool cut_lo = !(u0.is_thin() && u0.lo() == 0);
    if (!cut_hi && !cut_lo) return;
    // Within [0, u1] the new lower end is at u0 / u1 (u1 >= u0 > 0 when cut).
    const Interval r =
        cut_lo ? intersect(cut_hi ? u0 / u1 : u0, Interval(0.0, 1.0)) : Interval(0.0);
    if (lanes::moderate(c, sh.size(), 0x1p1000) && !r.is_empty()) {
        const PassWeights left(u1), right(r);
        with_degree(dir == 0 ? sh.p : sh.q, [&](auto n) {
            restrict_rows_lanes(c, sh, dir, n, cut_hi ? &left : nullptr, cut_lo ? &right : nullptr);
        });
        return;
    }
    if (cut_hi) for_rows(c, sh, dir, [&](Interval* r, int n, int st) { left_part(r, n, st, u1); });
    if (!cut_lo) return;
    for_rows(c, sh, dir, [&](Interval* row, int n, int st) { right_part(row, n, st, r); });
}

void split_subpatch(const Interval* c, SubpatchShape sh, int dir, Interval u, Interval* lo,
                    Interval* hi) {
    u = intersect(u, Interval(0.0, 1.0));
    SEAMLESS_CHECK(!u.is_empty(), "the split parameter meets [0, 1]");
    const bool at_end = u.is_thin() && (u.lo() == 0 || u.lo() == 1); // a pass skipped
    if (!at_end && lanes::moderate(c, sh.size(), 0x1p1000)) {
        const PassWeights w(u);
        with_degree(dir == 0 ? sh.p : sh.q,
                    [&](auto n) { split_rows_lanes(c, sh, dir, n, w, lo, hi); });
        return;
    }
    std::copy_n(c, sh.size(), lo);
    std::copy_n(c, sh.size(), hi);
    restrict_subpatch(lo, sh, dir, Interval(0.0), u);
    restrict_subpatch(hi, sh, dir, u, Interval(1.0));
}

IVec<3> subpatch_hull(const Interval* c, SubpatchShape sh) {
    IVec<3> h = IVec<3>::empty();
    if (sh.dim == 4)
        for (int i = 0; i <= sh.p; ++i)
            for (int j = 0; j <= sh.q; ++j)
                if (!(c[sh.index(3, i, j)].lo() > 0)) {
                    for (int d = 0; d < 3; ++d) h[d] = Interval::entire();
                    return h;
                }
    // On lane pairs where no quotient can overflow (the same bits as the
    // scalar loop below): every bound below 2^500, every weight >= 2^-500.
    const int n = (sh.p + 1) * (sh.q + 1);
    const Interval* w = c + sh.index(3, 0, 0);
    bool far_from_zero = true;
    for (int k = 0; sh.dim == 4 && k < n; ++k) far_from_zero &= w[k].lo() >= 0x1p-500;
    if (far_from_zero && lanes::moderate(c, sh.size(), 0x1p500)) {
        using namespace lanes;
        Lanes l[3] = {lanes::empty(), lanes::empty(), lanes::empty()};
        for (int k = 0; k < n; ++k)
            for (int d = 0; d < 3; ++d) {
                Lanes x = load(c[d * n + k]);
                if (sh.dim == 4) x = quotient_positive(x, splat(w[k].lo()), splat(w[k].hi()));
                l[d] = lanes::hull(l[d], x);
            }
        for (int d = 0; d < 3; ++d) h[d] = store(l[d]);
        return h;
    }
    for (int i = 0; i <= sh.p; ++i)
        for (int j = 0; j <= sh.q; ++j)
            for (int d = 0; d < 3; ++d) {
                Interval x = c[sh.index(d, i, j)];
                if (sh.dim == 4) x = x / c[sh.index(3, i, j)];
                h[d] = hull(h[d], x);
            }
    return h;
}

bool subpatch_projection(const Interval* c, SubpatchShape sh, Interval& a, Interval& b) {
    // On lane pairs where no quotient can overflow: x, y, z below 2^500 and
    // every z at least 2^-500 (the same bits as the scalar loop below).
    const int n = (sh.p + 1) * (sh.q + 1);
    const Interval* x = c + sh.index(0, 0, 0);
    const Interval* y = c + sh.index(1, 0, 0);
    const Interval* z = c + sh.index(2, 0, 0);
    bool far_from_zero = true;
    for (int k = 0; k < n; ++k) far_from_zero &= z[k].lo() >= 0x1p-500;
    if (far_from_zero && lanes::moderate(c, 3 * n, 0x1p500)) {
        using namespace lanes;
        Lanes la = lanes::empty(), lb = lanes::empty();
        for (int k = 0; k < n; ++k) {
            const Lanes zl = splat(z[k].lo()), zh = splat(z[k].hi());
            la = lanes::hull(la, quotient_positive(load(x[k]), zl, zh));
            lb = lanes::hull(lb, quotient_positive(load(y[k]), zl, zh));
        }
        a = store(la);
        b = store(lb);
        return true;
    }
    a = b = Interval::empty();
    for (int i = 0; i <= sh.p; ++i)
        for (int j = 0; j <= sh.q; ++j) {
            const Interval z = c[sh.index(2, i, j)];
            if (!(z.lo() > 0)) return false;
            a = hull(a, c[sh.index(0, i, j)] / z);
            b = hull(b, c[sh.index(1, i, j)] / z);
        }
    return true;
}

} // namespace seamless
