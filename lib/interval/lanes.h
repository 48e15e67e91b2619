// SPDX-License-Identifier: MIT
// Intervals as lane pairs (-lo, hi) of doubles in a 2-lane GCC vector: with
// the lower bound negated, both bounds round UP, and next_down(x) =
// -next_up(-x) makes every result bit for bit that of the scalar Interval
// operations of interval.h (round to nearest, then one ulp outward; paper
// section 2). Only for finite operands whose results cannot overflow: callers
// check magnitudes first (moderate()) and keep the scalar code as fallback.
#pragma once

#include <seamless/interval/interval.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless::lanes {

using Lanes = double __attribute__((vector_size(16)));
using LaneBits = long long __attribute__((vector_size(16)));

inline Lanes splat(double d) {
    return Lanes{d, d};
}
// next_up in both lanes of finite x: x + 0 turns -0 into +0 (round to
// nearest), then one ulp up is +1 on the bits of x >= 0 and -1 below 0: the
// mask x < 0 (all ones, -1, or 0) or 1.
inline Lanes up(Lanes x) {
    x = x + Lanes{0.0, 0.0};
    const LaneBits neg = x < Lanes{0.0, 0.0}; // -1 where negative
    return reinterpret_cast<Lanes>(reinterpret_cast<LaneBits>(x) + (neg | 1));
}
inline Lanes load(const Interval& c) {
    return Lanes{-c.lo(), c.hi()};
}
inline Interval store(Lanes x) {
    return {-x[0], x[1]};
}
// (hi, -lo): the lanes of -x, exact.
inline Lanes swap(Lanes x) {
    return __builtin_shufflevector(x, x, 1, 0);
}
// a - b as Interval's operator-: lanes (-a.lo + b.hi, a.hi - b.lo), rounded up
// (-(a.lo - b.hi) is exactly -a.lo + b.hi: round to nearest is symmetric).
inline Lanes sub(Lanes a, Lanes b) {
    return up(a + swap(b));
}
// Where b > a, b, else a, per lane: hull(a, b) of interval.h on the negated
// lower bound too (std::min(a.lo, b.lo) keeps a unless b.lo < a.lo), so even
// the sign of a zero bound agrees. The empty interval is (-inf, -inf). The
// selection b > a ? b : a is one maxpd on x86 (a blend of masks is four).
inline Lanes hull(Lanes a, Lanes b) {
    return b > a ? b : a;
}
inline Lanes empty() {
    return splat(-std::numeric_limits<double>::infinity());
}

// A fixed factor e for products e z: its bounds in both lanes and negated.
struct Factor {
    Lanes lo, hi, neg_lo, neg_hi;
    explicit Factor(Interval e)
        : lo(splat(e.lo())), hi(splat(e.hi())), neg_lo(splat(-e.lo())), neg_hi(splat(-e.hi())) {}
};
// e z as Interval's operator*: the lanes of z times e.lo and e.hi give
// (-e.lo z.lo, e.lo z.hi) and (-e.hi z.lo, e.hi z.hi), those of -z the other
// two products of each sign, and the lane maxima are (-min, max) of the four
// products. The scalar sign cases pick the exact extreme product; rounding to
// nearest is monotone, so its rounding is the maximum here (a zero's sign
// aside, which up() drops).
inline Lanes mul(const Factor& e, Lanes z) {
    const Lanes s = swap(z);
    return up(hull(hull(z * e.lo, z * e.hi), hull(s * e.neg_lo, s * e.neg_hi)));
}
// w x for w >= 0 given as its bounds in both lanes, rounded up: the bound is
// w.hi x where the lane x > 0, else w.lo x (a zero x gives a zero either way).
// That is the larger of w.lo x and w.hi x (rounding to nearest is monotone
// and w.lo <= w.hi; equal products have equal bits but for a zero's sign,
// which up() drops): two products and a maximum instead of a sign mask.
inline Lanes weight_up(Lanes wlo, Lanes whi, Lanes x) {
    return up(hull(wlo * x, whi * x));
}

// x / z as Interval's operator/ for z > 0 given as its bounds in both lanes:
// (-x.lo, x.hi) / z.lo and / z.hi are (-q1, q3) and (-q2, q4) of the four
// quotients q1 = x.lo / z.lo, q2 = x.lo / z.hi, q3 = x.hi / z.lo, q4 = x.hi /
// z.hi; since x.lo <= x.hi and rounding is monotone, min q = min(q1, q2) and
// max q = max(q3, q4): the lane maxima, rounded up. Only for quotients that
// cannot overflow (|x| < 2^500 and z.lo >= 2^-500, say).
inline Lanes quotient_positive(Lanes x, Lanes zlo, Lanes zhi) {
    return up(hull(x / zlo, x / zhi));
}

// Every bound of c[0..size) of magnitude below limit (false for an infinite
// or NaN bound): the condition of a lane path.
// Branch-free on lane pairs (lo, hi): the magnitudes' sign bits cleared, a
// mask of |bound| < limit kept over all of them (false for NaN too).
inline bool moderate(const Interval* c, int size, double limit) {
    const Lanes lim = splat(limit);
    LaneBits ok = {-1, -1};
    for (int k = 0; k < size; ++k) {
        const LaneBits bits = reinterpret_cast<LaneBits>(Lanes{c[k].lo(), c[k].hi()});
        const Lanes a = reinterpret_cast<Lanes>(bits & 0x7fffffffffffffffLL);
        ok &= a < lim;
    }
    return (ok[0] & ok[1]) != 0;
}

} // namespace seamless::lanes
