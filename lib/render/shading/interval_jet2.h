// SPDX-License-Identifier: MIT
// Second-order forward differentiation over intervals: a function of the
// screen point (a, b) over a cluster B, held as enclosures over B of its value,
// its two partials and its three second partials. Every operation applies the
// chain rule to the enclosures (outward rounded, interval.h), so each entry
// encloses the true derivative at every point of B where the function is
// twice differentiable.
//
// Used for step 9's second-order criterion (second_order.h), whose bound needs
// |I_aa| and |I_bb| over B where I is C^2 there. Where a piece is only
// Lipschitz (a clamp max(0, f) whose argument changes sign in B), the
// first partials are the hull of the pieces' (as in interval_jet.h, enough
// for the first-order bound) and the second partials are entire: the
// second-order bound is then not used. A possible jump makes every partial
// entire.
#pragma once

#include <seamless/interval/interval.h>
#include <seamless/render/shading/interval_jet.h>
#include <seamless/render/shading/shading.h> // power(Interval, double)

#include <algorithm>

namespace seamless {

struct IntervalJet2 {
    Interval v, da, db, daa, dab, dbb; // value, d/da, d/db, d2/da2, d2/dadb, d2/db2 over B

    IntervalJet2() = default;
    IntervalJet2(double x) : v(x) {}   // NOLINT: implicit, a constant
    IntervalJet2(Interval x) : v(x) {} // NOLINT: implicit, a constant
    IntervalJet2(Interval x, Interval xa, Interval xb, Interval xaa, Interval xab, Interval xbb)
        : v(x), da(xa), db(xb), daa(xaa), dab(xab), dbb(xbb) {}

    double lo() const { return v.lo(); }
    double hi() const { return v.hi(); }
    // The first-order part (interval_jet.h).
    IntervalJet first() const { return {v, da, db}; }
};

inline IntervalJet2 operator+(const IntervalJet2& x, const IntervalJet2& y) {
    return {x.v + y.v, x.da + y.da, x.db + y.db, x.daa + y.daa, x.dab + y.dab, x.dbb + y.dbb};
}
inline IntervalJet2 operator-(const IntervalJet2& x, const IntervalJet2& y) {
    return {x.v - y.v, x.da - y.da, x.db - y.db, x.daa - y.daa, x.dab - y.dab, x.dbb - y.dbb};
}
inline IntervalJet2 operator-(const IntervalJet2& x) {
    return {-x.v, -x.da, -x.db, -x.daa, -x.dab, -x.dbb};
}
// (xy)'' = x'' y + 2 x' y' + x y'' (Leibniz).
inline IntervalJet2 operator*(const IntervalJet2& x, const IntervalJet2& y) {
    const Interval two(2.0);
    return {x.v * y.v,
            x.da * y.v + x.v * y.da,
            x.db * y.v + x.v * y.db,
            x.daa * y.v + two * (x.da * y.da) + x.v * y.daa,
            x.dab * y.v + x.da * y.db + x.db * y.da + x.v * y.dab,
            x.dbb * y.v + two * (x.db * y.db) + x.v * y.dbb};
}
// q = x / y from x = q y: q' = (x' - q y') / y, q'' = (x'' - 2 q' y' - q y'') / y
// (mixed: (x_ab - q_a y_b - q_b y_a - q y_ab) / y); 0 in y gives entire partials.
inline IntervalJet2 operator/(const IntervalJet2& x, const IntervalJet2& y) {
    const Interval two(2.0);
    const Interval q = x.v / y.v;
    const Interval qa = (x.da - q * y.da) / y.v, qb = (x.db - q * y.db) / y.v;
    return {q,
            qa,
            qb,
            (x.daa - two * (qa * y.da) - q * y.daa) / y.v,
            (x.dab - qa * y.db - qb * y.da - q * y.dab) / y.v,
            (x.dbb - two * (qb * y.db) - q * y.dbb) / y.v};
}

// r = sqrt x from x = r^2: r' = x' / (2 r), r'' = (x'' - 2 r'^2) / (2 r)
// (mixed: (x_ab - 2 r_a r_b) / (2 r)); entire where x may vanish.
inline IntervalJet2 root(const IntervalJet2& x) {
    const Interval two(2.0);
    const Interval r = sqrt(x.v);
    const Interval twice = two * r;
    const Interval ra = x.da / twice, rb = x.db / twice;
    return {r,
            ra,
            rb,
            (x.daa - two * sqr(ra)) / twice,
            (x.dab - two * (ra * rb)) / twice,
            (x.dbb - two * sqr(rb)) / twice};
}

// f(x) with f' = d1 and f'' = d2 enclosed over x's values (chain rule:
// (f o x)_ab = f'' x_a x_b + f' x_ab).
inline IntervalJet2 chain(Interval fv, Interval d1, Interval d2, const IntervalJet2& x) {
    return {fv,
            d1 * x.da,
            d1 * x.db,
            d2 * sqr(x.da) + d1 * x.daa,
            d2 * (x.da * x.db) + d1 * x.dab,
            d2 * sqr(x.db) + d1 * x.dbb};
}

// A Lipschitz function that is one of two pieces, each twice differentiable:
// the hull of the pieces' first partials, no bound on the second.
inline IntervalJet2 kink(Interval v, const IntervalJet2& a, const IntervalJet2& b) {
    const Interval any = Interval::entire();
    return {v, hull(a.da, b.da), hull(a.db, b.db), any, any, any};
}
// clamp0, clamp01: the templates of interval_jet.h, with this kink.
// A cosine: the true values never leave [-1, 1], so cutting the enclosure
// there changes no true value and no derivative.
inline IntervalJet2 cosine_range(const IntervalJet2& x) {
    IntervalJet2 r = x;
    r.v = intersect(x.v, Interval(-1.0, 1.0));
    return r;
}
// x^s for x >= 0: f' = s x^(s-1), f'' = s (s-1) x^(s-2). For s >= 2 both are
// bounded (x^e is monotone for e >= 0, shading.h); below that they are
// bounded only where x > 0 (x^(s-k) = x^s / x^k), and entire otherwise.
inline IntervalJet2 power(const IntervalJet2& x, double s) {
    const Interval v = power(x.v, s);
    const Interval S(s), S1 = Interval(s) * (Interval(s) - Interval(1.0));
    Interval d1 = Interval::entire(), d2 = Interval::entire();
    if (s >= 2) {
        d1 = S * power(x.v, s - 1);
        d2 = S1 * power(x.v, s - 2);
    } else if (x.v.lo() > 0) {
        d1 = S * v / x.v;
        d2 = S1 * v / sqr(x.v);
    } else if (s >= 1) {
        d1 = S * power(x.v, s - 1);
    }
    return chain(v, d1, d2, x);
}
// Either of two functions, maybe with a jump between them: no derivative bound.
inline IntervalJet2 either(const IntervalJet2& x, const IntervalJet2& y) {
    const Interval any = Interval::entire();
    return {hull(x.v, y.v), any, any, any, any, any};
}
// Anything in [0, 1] (an undecided side of the surface).
inline IntervalJet2 unit_range(const IntervalJet2&) {
    const Interval any = Interval::entire();
    return {Interval(0.0, 1.0), any, any, any, any, any};
}
// surely_positive, surely_negative, possibly_zero_crossing: interval_jet.h.

} // namespace seamless
