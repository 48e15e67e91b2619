// SPDX-License-Identifier: MIT
// Forward-mode differentiation over intervals: a function of the screen point
// (a, b) over a cluster B, held as the enclosure of its values together with
// enclosures of its two partial derivatives over B. Every operation applies
// the chain rule to the enclosures (outward rounded, interval.h), so the
// partials enclose the true gradient at every point of B where the function is
// differentiable.
//
// Used for the depth's second partials in surface_jets.h (the partials of
// Z_a = -Z N_x / (N . d)); step 9's second-order criterion (second_order.h)
// uses the second-order jets of interval_jet2.h, whose first partials follow
// the same rules. Functions that are only Lipschitz (a
// clamp max(0, f)) are allowed: along a segment their derivative is, almost
// everywhere, that of one of the pieces, so the hull of the pieces' partials
// still bounds every difference quotient. A jump (a specular term cut off when
// the light passes behind the surface) has no such bound: its partials are the
// entire line, which makes the criterion fail, never pass wrongly.
#pragma once

#include <seamless/interval/interval.h>
#include <seamless/render/shading/shading.h> // power(Interval, double)

#include <algorithm>
#include <limits>

namespace seamless {

struct IntervalJet {
    Interval v, da, db; // value, d/da, d/db over the cluster

    IntervalJet() = default;
    IntervalJet(double x) : v(x) {}   // NOLINT: implicit, a constant
    IntervalJet(Interval x) : v(x) {} // NOLINT: implicit, a constant
    IntervalJet(Interval x, Interval xa, Interval xb) : v(x), da(xa), db(xb) {}

    double lo() const { return v.lo(); }
    double hi() const { return v.hi(); }
};

inline IntervalJet operator+(const IntervalJet& x, const IntervalJet& y) {
    return {x.v + y.v, x.da + y.da, x.db + y.db};
}
inline IntervalJet operator-(const IntervalJet& x, const IntervalJet& y) {
    return {x.v - y.v, x.da - y.da, x.db - y.db};
}
inline IntervalJet operator-(const IntervalJet& x) {
    return {-x.v, -x.da, -x.db};
}
inline IntervalJet operator*(const IntervalJet& x, const IntervalJet& y) {
    return {x.v * y.v, x.da * y.v + x.v * y.da, x.db * y.v + x.v * y.db};
}
// (x / y)' = (x' - (x / y) y') / y; 0 in y gives entire partials (operator/).
inline IntervalJet operator/(const IntervalJet& x, const IntervalJet& y) {
    const Interval q = x.v / y.v;
    return {q, (x.da - q * y.da) / y.v, (x.db - q * y.db) / y.v};
}

// sqrt: (sqrt x)' = x' / (2 sqrt x); not differentiable where x may vanish
// (the division by an interval holding 0 is entire).
inline IntervalJet root(const IntervalJet& x) {
    const Interval r = sqrt(x.v);
    const Interval twice = Interval(2.0) * r;
    return {r, x.da / twice, x.db / twice};
}

// Partials of a Lipschitz function that is one of two pieces, each
// differentiable: the hull of the pieces' partials (see the top of the file).
inline IntervalJet kink(Interval v, const IntervalJet& a, const IntervalJet& b) {
    return {v, hull(a.da, b.da), hull(a.db, b.db)};
}
// The clamps of the shading model for any interval jet (this one and
// IntervalJet2 of interval_jet2.h): kink() of the jet's own type (found by
// argument-dependent lookup) where the clamp may bend inside the enclosure.
template <class Jet>
concept IntervalJetType = requires(const Jet& j) {
    j.v;
    j.da;
    j.db;
};
template <IntervalJetType Jet> Jet clamp0(const Jet& x) {
    if (x.v.lo() >= 0) return x;
    if (x.v.hi() <= 0) return Jet(0.0);
    return kink(Interval(0.0, x.v.hi()), x, Jet(0.0));
}
template <IntervalJetType Jet> Jet clamp01(const Jet& x) {
    if (x.v.lo() >= 0 && x.v.hi() <= 1) return x;
    if (x.v.hi() <= 0) return Jet(0.0);
    if (x.v.lo() >= 1) return Jet(1.0);
    return kink(Interval(std::clamp(x.v.lo(), 0.0, 1.0), std::clamp(x.v.hi(), 0.0, 1.0)), x,
                Jet(0.0));
}
// A cosine: the true values never leave [-1, 1], so cutting the enclosure
// there changes no true value and no derivative.
inline IntervalJet cosine_range(const IntervalJet& x) {
    return {intersect(x.v, Interval(-1.0, 1.0)), x.da, x.db};
}
// x^s for x >= 0: (x^s)' = s x^(s-1) x', bounded for s >= 1; for s < 1 the
// derivative is unbounded near 0 and is taken as entire unless x > 0 there.
inline IntervalJet power(const IntervalJet& x, double s) {
    const Interval v = power(x.v, s);
    Interval d = Interval::entire();
    if (s >= 1)
        d = Interval(s) * power(x.v, s - 1); // power() of shading.h: x^e monotone for e >= 0
    else if (x.v.lo() > 0)
        d = Interval(s) * v / x.v; // s x^s / x
    return {v, d * x.da, d * x.db};
}
// Either of two functions, maybe with a jump between them: no derivative bound.
inline IntervalJet either(const IntervalJet& x, const IntervalJet& y) {
    return {hull(x.v, y.v), Interval::entire(), Interval::entire()};
}
// Anything in [0, 1] (an undecided side of the surface).
inline IntervalJet unit_range(const IntervalJet&) {
    return {Interval(0.0, 1.0), Interval::entire(), Interval::entire()};
}
// The sign tests of the shading model for any interval jet (value only).
template <IntervalJetType Jet> bool surely_positive(const Jet& x) {
    return x.v.lo() > 0;
}
template <IntervalJetType Jet> bool surely_negative(const Jet& x) {
    return x.v.hi() < 0;
}
template <IntervalJetType Jet> bool possibly_zero_crossing(const Jet& x) {
    return x.v.lo() <= 0 && x.v.hi() >= 0;
}

} // namespace seamless
