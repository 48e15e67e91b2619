// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/interval/lanes.h>
#include <seamless/spline/enclosure/polynomial_range.h>
#include <seamless/spline/enclosure/subpatch.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless {
namespace {

constexpr int K = PowerForm::kMaxOrder;

thread_local long long range_enclosures = 0;

// The kernels below take the degree n as an int or as a std::integral_constant
// (with_degree, subpatch.h: degrees 1 to 3, nearly every patch and system of
// the scenes), so that their loops unroll: the same operations in the same
// order either way, hence the same bits (the library is built without fused or
// reassociated operations). Arrays are not zeroed: only entries 0..n are read.

// Horner with interval coefficients.
template <class Deg> Interval horner1(const Interval* c, Deg n, Interval u) {
    Interval r = c[n];
    for (int i = n - 1; i >= 0; --i) r = r * u + c[i];
    return r;
}
// Horner with real coefficients (exact doubles).
template <class Deg> Interval horner1(const double* c, Deg n, Interval u) {
    Interval r(c[n]);
    for (int i = n - 1; i >= 0; --i) r = r * u + Interval(c[i]);
    return r;
}

// Horner at a point in doubles, with a rigorous error bound instead of
// interval operations: without fused operations (the library is built with
// -ffp-contract=off), |p(x) - fl(p(x))| <= gamma_2n sum |c_i| |x|^i, gamma_k =
// k u / (1 - k u), u = 2^-53 (Higham, Accuracy and Stability of Numerical
// Algorithms, 2nd ed., eq. 5.3), plus an absolute term for gradual underflow.
// The sum is itself computed by Horner, so it is divided by (1 - gamma) too,
// and the bound is rounded up generously (k = 2n + 4, three ulps). Far cheaper
// than interval Horner at a point, which it replaces.
template <class Deg> Interval horner_point(const double* c, Deg n, double x) {
    double r = c[n], s = std::abs(c[n]);
    const double ax = std::abs(x);
    for (int i = n - 1; i >= 0; --i) {
        r = r * x + c[i];
        s = s * ax + std::abs(c[i]);
    }
    if (!std::isfinite(r) || !std::isfinite(s)) return horner1(c, n, Interval(x));
    constexpr double u = 0x1p-53;
    const double k = 2.0 * n + 4;
    const double g = k * u / (1 - k * u);
    double e = g * s / (1 - g);
    e += underflow_allowance(4.0 * n + 4);
    e = next_up(next_up(next_up(e)));
    return {next_down(r - e), next_up(r + e)};
}

// Bounds below this magnitude, u in [0, 1] and at most kMaxOrder terms: no
// sum, product or error bound below can overflow, so the lane forms of
// lanes.h (finite operands only) give the scalar operations' bits.
constexpr double kModerate = 0x1p900;

// horner_point at x0 of c0 and at x1 of c1 at once, one in each lane (the
// same operations, each rounded once to nearest, in the same order; the
// bounds -lo and hi rounded up as lanes.h does: next_down(r - e) is
// -next_up(e - r), round to nearest being symmetric). For coefficients below
// kModerate = 2^900 in magnitude and x0, x1 in [0, 1]: then |r| and s stay
// below 10 2^900 (1 + 2^-52)^20 < 2^904, so horner_point's isfinite test
// passes and nothing below overflows (lanes.h's condition).
template <class Deg>
[[gnu::always_inline]] inline void horner_point2(const double* c0, const double* c1, Deg n,
                                                 double x0, double x1, Interval& p0, Interval& p1) {
    using lanes::LaneBits;
    using lanes::Lanes;
    const auto vabs = [](Lanes v) {
        return reinterpret_cast<Lanes>(reinterpret_cast<LaneBits>(v) & 0x7fffffffffffffffLL);
    };
    const Lanes x{x0, x1}, ax = vabs(x);
    Lanes r{c0[n], c1[n]};
    Lanes s = vabs(r);
    for (int i = n - 1; i >= 0; --i) {
        const Lanes ci{c0[i], c1[i]};
        r = r * x + ci;
        s = s * ax + vabs(ci);
    }
    constexpr double u = 0x1p-53;
    const double k = 2.0 * n + 4;
    const double g = k * u / (1 - k * u);
    Lanes e = lanes::splat(g) * s / lanes::splat(1 - g);
    e = e + lanes::splat(underflow_allowance(4.0 * n + 4));
    e = lanes::up(lanes::up(lanes::up(e)));
    const Lanes neg_lo = lanes::up(e - r), hi = lanes::up(r + e);
    p0 = {-neg_lo[0], hi[0]};
    p1 = {-neg_lo[1], hi[1]};
}

// The slope horner1(dc, n - 1, u) of real_polynomial_range below in lanes
// (lanes.h) for u in [0, 1] and moderate c: dc_i = (i + 1) c_(i+1) is
// [next_down, next_up] of the product in every sign case of operator*, and
// r u for u >= 0 is weight_up's bound in each lane.
template <class Deg> Interval slope_lanes(const double* c, Deg n, Interval u) {
    using lanes::Lanes;
    const Lanes ulo = lanes::splat(u.lo()), uhi = lanes::splat(u.hi());
    const auto dc = [&](int i) { return lanes::up(lanes::splat(double(i)) * Lanes{-c[i], c[i]}); };
    Lanes r = dc(n);
    for (int i = n - 1; i >= 1; --i) r = lanes::up(lanes::weight_up(ulo, uhi, r) + dc(i));
    return lanes::store(r);
}

// Range of a real polynomial over u where its derivative may change sign:
// Horner intersected with the mean value form (Proposition 1).
template <class Deg>
[[gnu::noinline]] Interval mean_value_range(const double* c, Deg n, Interval u, Interval slope) {
    const double m = u.mid();
    const Interval mvf = horner_point(c, n, m) + slope * (u - Interval(m));
    return intersect(horner1(c, n, u), mvf);
}

// Range of a real polynomial over a non-thin u >= 0: the end values where the
// derivative has one sign, else mean_value_range.
template <class Deg> Interval real_range_scalar(const double* c, Deg n, Interval u) {
    Interval dc[K]; // derivative coefficients i * c_i, outward rounded
    for (int i = 1; i <= n; ++i) dc[i - 1] = Interval(double(i)) * Interval(c[i]);
    const Interval slope = horner1(dc, n - 1, u);
    if (slope.lo() >= 0 || slope.hi() <= 0) // monotone: range at the ends
        return hull(horner_point(c, n, u.lo()), horner_point(c, n, u.hi()));
    return mean_value_range(c, n, u, slope);
}
// The same in lanes (slope_lanes, horner_point2) for u in [0, 1] and moderate
// c: the same bits (tests/spline/fast_range_test.cpp).
template <class Deg> Interval real_range_lanes(const double* c, Deg n, Interval u) {
    const Interval slope = slope_lanes(c, n, u);
    if (!(slope.lo() >= 0 || slope.hi() <= 0)) return mean_value_range(c, n, u, slope);
    Interval a, b;
    horner_point2(c, c, n, u.lo(), u.hi(), a, b);
    return hull(a, b);
}

// Range of a real polynomial over u >= 0. fast: u in [0, 1] and c moderate
// (the caller's checks).
template <class Deg>
inline Interval real_polynomial_range(const double* c, Deg n, Interval u, bool fast) {
    if (n == 0) return Interval(c[0]);
    if (u.is_thin()) return horner_point(c, n, u.lo());
    return fast ? real_range_lanes(c, n, u) : real_range_scalar(c, n, u);
}

// Range over u in [0, 1] of sum c_i u^i with narrow interval coefficients
// c_i = [lo_i, hi_i]: with m_i = (lo_i + hi_i) / 2 in c_i, |c_i - m_i| <= w_i =
// hi_i - lo_i, so the range lies in that of the real polynomial sum m_i u^i
// widened by R >= sum w_i u^i <= sum w_i. R is the computed sum bounded from
// above like the error term of horner_point (non-negative terms; one more
// rounding per w_i, hence k = n + 4 below, and an absolute term for
// subnormals). One real range instead of Lemma 2's two.
template <class Deg>
Interval narrow_polynomial_range(const double* lo, const double* hi, Deg n, Interval u, bool fast) {
    double m[K];
    double s = 0;
    for (int i = 0; i <= n; ++i) {
        m[i] = 0.5 * lo[i] + 0.5 * hi[i];
        s += hi[i] - lo[i];
    }
    constexpr double eps = 0x1p-53;
    const double k = n + 4;
    const double g = k * eps / (1 - k * eps);
    double R = s / (1 - g) + underflow_allowance(4.0 * n + 4);
    R = next_up(next_up(next_up(R)));
    const Interval rm = real_polynomial_range(m, n, u, fast);
    return {next_down(rm.lo() - R), next_up(rm.hi() + R)};
}

// Lemma 2 on coefficients given by their bounds lo_i <= c_i <= hi_i, u >= 0:
// the range is [min sum lo_i u^i, max sum hi_i u^i]. unit: u is in [0, 1]
// (the lane forms apply to moderate coefficients; false: the scalar reference).
template <class Deg>
Interval bounds_range(const double* lo, const double* hi, Deg n, Interval u, bool unit) {
    bool thin = true;
    double wmax = 0, mmax = 0;
    bool moderate = unit; // every bound below kModerate (then so is every m_i below)
    for (int i = 0; i <= n; ++i) {
        thin &= lo[i] == hi[i];
        wmax = std::max(wmax, hi[i] - lo[i]);
        const double mag = std::abs(lo[i]) + std::abs(hi[i]);
        mmax = std::max(mmax, mag);
        moderate &= mag < kModerate; // false for NaN
    }
    const bool fast = moderate;
    if (thin) return real_polynomial_range(lo, n, u, fast);
    // Coefficients as narrow as rounding leaves them (power forms of a patch, a
    // single ray's system): one real range instead of two; Lemma 2 would gain
    // at most the widening by their widths.
    if (wmax <= 0x1p-30 * mmax && mmax < std::numeric_limits<double>::infinity() && u.hi() <= 1)
        return narrow_polynomial_range(lo, hi, n, u, fast);
    if (fast && n > 0 && u.is_thin()) { // both at one point
        Interval rl, rh;
        horner_point2(lo, hi, n, u.lo(), u.lo(), rl, rh);
        return {rl.lo(), rh.hi()};
    }
    const Interval rl = real_polynomial_range(lo, n, u, fast);
    const Interval rh = real_polynomial_range(hi, n, u, fast);
    return {rl.lo(), rh.hi()};
}

// polynomial_range of the coefficients c[0], c[stride], ..., c[n stride]
// (a row or a column of a power form, read in place); unit: u is in [0, 1].
template <class Deg>
Interval strided_range(const Interval* c, int stride, Deg n, Interval u, bool unit) {
    if (!unit) {
        if (u.is_empty()) return Interval::empty();
        if (u.lo() < 0) {
            Interval cc[K];
            for (int i = 0; i <= n; ++i) cc[i] = c[i * stride];
            return horner1(cc, n, u);
        }
    }
    double lo[K], hi[K];
    for (int i = 0; i <= n; ++i) {
        lo[i] = c[i * stride].lo();
        hi[i] = c[i * stride].hi();
    }
    return bounds_range(lo, hi, n, u, unit);
}

// The outer range of horner() over the inner ranges [lo_i, hi_i].
template <class Deg>
Interval outer_range(const double* lo, const double* hi, Deg n, Interval u, bool unit) {
    if (unit) return bounds_range(lo, hi, n, u, true);
    Interval b[K];
    for (int i = 0; i <= n; ++i) b[i] = {lo[i], hi[i]};
    return strided_range(b, 1, n, u, false);
}

// horner() with the degrees as ints or integral constants (with_degree);
// unit: the box lies in [0,1]^2 (false: the scalar reference throughout).
template <class P, class Q>
Interval horner_rows(const PowerForm& f, int c, ParamBox box, P p, Q q, bool unit) {
    double lo[K], hi[K];
    const Interval* a = &f.at(c, 0, 0);
    const int row = q + 1; // packed rows (power_form.h): a constant for a fixed q
    // Section 5: sum_i b_i(t) s^i if [t] is narrower, else sum_j c_j(s) t^j.
    if (box.t.rad() <= box.s.rad()) {
        for (int i = 0; i <= p; ++i) {
            const Interval b = strided_range(a + i * row, 1, q, box.t, unit);
            lo[i] = b.lo();
            hi[i] = b.hi();
        }
        return outer_range(lo, hi, p, box.s, unit);
    }
    for (int j = 0; j <= q; ++j) {
        const Interval b = strided_range(a + j, row, p, box.s, unit);
        lo[j] = b.lo();
        hi[j] = b.hi();
    }
    return outer_range(lo, hi, q, box.t, unit);
}

// u nonempty inside [0, 1] (NaN bounds fail).
bool in_unit(Interval u) {
    return u.lo() >= 0 && u.lo() <= u.hi() && u.hi() <= 1;
}

// with_degree (subpatch.h) with degree 0 a constant too: the constant
// directions of planes and of derivatives of bilinear patches.
template <class F> Interval with_range_degree(int n, F f) {
    if (n == 0) return f(std::integral_constant<int, 0>{});
    return with_degree(n, f);
}

} // namespace

Interval polynomial_range(const Interval* c, int n, Interval u) {
    SEAMLESS_CHECK(n >= 0 && n < K, "a degree below kMaxOrder");
    return with_range_degree(n, [&](auto m) { return strided_range(c, 1, m, u, in_unit(u)); });
}

Interval polynomial_range_generic(const Interval* c, int n, Interval u) {
    SEAMLESS_CHECK(n >= 0 && n < K, "a degree below kMaxOrder");
    return strided_range(c, 1, n, u, false);
}

long long range_enclosure_count() {
    return range_enclosures;
}

Interval horner(const PowerForm& f, int c, ParamBox box) {
    ++range_enclosures;
    return with_range_degree(f.p, [&](auto p) {
        return with_range_degree(f.q, [&](auto q) {
            return horner_rows(f, c, box, p, q, in_unit(box.s) && in_unit(box.t));
        });
    });
}

Interval horner_generic(const PowerForm& f, int c, ParamBox box) {
    return horner_rows(f, c, box, f.p, f.q, false);
}

// Coordinate c of f's derivative along s (dir 0) or t (dir 1) over a box: the
// nested ranges of horner() on the coefficients (i + 1) a_(i+1)j (or
// (j + 1) a_i(j+1)), formed on the fly (exact integers times intervals,
// outward rounded), so no power form is built or zeroed.
Interval horner_derivative(const PowerForm& f, int c, int dir, ParamBox box) {
    ++range_enclosures;
    const int p = dir == 0 ? f.p - 1 : f.p, q = dir == 1 ? f.q - 1 : f.q;
    if (p < 0 || q < 0) return Interval(0.0);
    auto coef = [&](int i, int j) {
        return dir == 0 ? Interval(i + 1.0) * f.at(c, i + 1, j)
                        : Interval(j + 1.0) * f.at(c, i, j + 1);
    };
    Interval b[K], inner[K];
    const bool t_inner = box.t.rad() <= box.s.rad();
    const int outer_n = t_inner ? p : q, inner_n = t_inner ? q : p;
    for (int i = 0; i <= outer_n; ++i) {
        for (int j = 0; j <= inner_n; ++j) inner[j] = t_inner ? coef(i, j) : coef(j, i);
        b[i] = polynomial_range(inner, inner_n, t_inner ? box.t : box.s);
    }
    return polynomial_range(b, outer_n, t_inner ? box.s : box.t);
}

} // namespace seamless
