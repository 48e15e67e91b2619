// SPDX-License-Identifier: MIT
// Closed real intervals with outward rounding (paper section 2).
//
// Every operation computes its bounds in round-to-nearest and then steps each
// bound one ulp outward (next_down / next_up). An IEEE operation rounded to
// nearest is within half an ulp of the exact result, so the stepped bounds
// enclose it: the enclosure never misses a true value. This needs no change of
// the FPU rounding mode, which keeps the code correct under any optimisation
// level and thread. The library is compiled with -ffp-contract=off so that no
// operation is fused into one with a different rounding.
//
// Why not Boost.Interval or CGAL::Interval_nt: both switch the rounding mode
// (Boost per operation unless the caller holds a rounding guard; CGAL through a
// Protect_FPU_rounding guard that every caller must hold), and CGAL's header
// drags CGAL into every stage of the pipeline. bench/interval_bench.cpp measures
// this type against Boost.Interval; docs/results/interval.md records the figures.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <ostream>

namespace seamless {

// The absolute error allowance of n roundings for gradual underflow. A
// rounding whose result is subnormal errs by at most denorm_min / 2, so n of
// them by n denorm_min / 2; n times the smallest NORMAL double (2^52 times
// denorm_min) bounds that with room to spare and is itself normal: an x86
// operation that produces or stores a subnormal takes a microcode assist, and
// the allowance n * denorm_min was such a subnormal in every point enclosure
// (docs/results/render.md).
inline double underflow_allowance(double n) {
    return n * std::numeric_limits<double>::min();
}

// The next representable double above x (x itself for +inf and NaN).
// Without branches on the sign: x + 0 turns -0 into +0 (round to nearest),
// whose successor is denorm_min; then one ulp up is +1 on the bits of a
// non-negative x and -1 on those of a negative one (-inf gives -max).
inline double next_up(double x) {
    if (!(x < std::numeric_limits<double>::infinity())) return x; // +inf or NaN
    const auto b = std::bit_cast<std::int64_t>(x + 0.0);
    return std::bit_cast<double>(b + ((b >> 63) | 1));
}
// The next representable double below x (x itself for -inf and NaN).
inline double next_down(double x) {
    return -next_up(-x);
}

class Interval {
  public:
    // The thin interval [0, 0].
    constexpr Interval() = default;
    // The thin interval [v, v]: v is taken as exact.
    constexpr Interval(double v) : lo_(v), hi_(v) {} // NOLINT: implicit by design
    // [lo, hi]; lo > hi gives the empty interval.
    constexpr Interval(double lo, double hi) : lo_(lo), hi_(hi) {}

    static constexpr Interval empty() {
        return {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    }
    static constexpr Interval entire() {
        return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    }
    // Hull of two reals that need not be ordered.
    static constexpr Interval hull(double a, double b) {
        return a <= b ? Interval(a, b) : Interval(b, a);
    }

    constexpr double lo() const { return lo_; }
    constexpr double hi() const { return hi_; }
    constexpr bool is_empty() const { return !(lo_ <= hi_); }
    constexpr bool is_thin() const { return lo_ == hi_; }
    bool is_finite() const { return std::isfinite(lo_) && std::isfinite(hi_); }
    // Midpoint, rounded to nearest (the paper's x-check); always inside the interval.
    double mid() const {
        if (lo_ == -hi_) return 0; // symmetric, also (-inf, inf)
        double m = 0.5 * lo_ + 0.5 * hi_;
        return std::clamp(m, lo_, hi_);
    }
    // Radius, rounded up, so that [mid - rad, mid + rad] contains the interval.
    double rad() const {
        double m = mid();
        return std::max(next_up(hi_ - m), next_up(m - lo_));
    }
    // Width hi - lo, rounded up.
    double width() const { return next_up(hi_ - lo_); }
    // Magnitude max |x| and mignitude min |x| (paper section 2).
    double mag() const { return std::max(std::abs(lo_), std::abs(hi_)); }
    double mig() const {
        return (lo_ <= 0 && hi_ >= 0) ? 0.0 : std::min(std::abs(lo_), std::abs(hi_));
    }

    constexpr bool contains(double x) const { return lo_ <= x && x <= hi_; }
    constexpr bool contains(Interval b) const {
        return b.is_empty() || (lo_ <= b.lo_ && b.hi_ <= hi_);
    }
    // b lies in the interior of this interval (Theorem 6 iii). A thin bound of
    // this interval counts as interior in its own coordinate, as in the paper's int(A).
    constexpr bool contains_in_interior(Interval b) const {
        if (is_thin()) return b.lo_ == lo_ && b.hi_ == hi_;
        return lo_ < b.lo_ && b.hi_ < hi_;
    }
    constexpr bool overlaps(Interval b) const { return lo_ <= b.hi_ && b.lo_ <= hi_; }

    friend constexpr bool operator==(Interval a, Interval b) {
        return (a.is_empty() && b.is_empty()) || (a.lo_ == b.lo_ && a.hi_ == b.hi_);
    }

    friend Interval operator+(Interval a, Interval b) {
        return {next_down(a.lo_ + b.lo_), next_up(a.hi_ + b.hi_)};
    }
    friend Interval operator-(Interval a, Interval b) {
        return {next_down(a.lo_ - b.hi_), next_up(a.hi_ - b.lo_)};
    }
    friend constexpr Interval operator-(Interval a) { return {-a.hi_, -a.lo_}; }
    friend Interval operator*(Interval a, Interval b) {
        // Sign cases (paper section 2, remark 2: most products need two real
        // multiplications); bounds with infinities (and empty or NaN bounds)
        // take the general path, out of line so that this part inlines.
        constexpr double big = std::numeric_limits<double>::max();
        if (a.lo_ >= -big && a.hi_ <= big && b.lo_ >= -big && b.hi_ <= big) [[likely]] {
            if (a.lo_ >= 0) {
                if (b.lo_ >= 0) return {next_down(a.lo_ * b.lo_), next_up(a.hi_ * b.hi_)};
                if (b.hi_ <= 0) return {next_down(a.hi_ * b.lo_), next_up(a.lo_ * b.hi_)};
                return {next_down(a.hi_ * b.lo_), next_up(a.hi_ * b.hi_)};
            }
            if (a.hi_ <= 0) {
                if (b.lo_ >= 0) return {next_down(a.lo_ * b.hi_), next_up(a.hi_ * b.lo_)};
                if (b.hi_ <= 0) return {next_down(a.hi_ * b.hi_), next_up(a.lo_ * b.lo_)};
                return {next_down(a.lo_ * b.hi_), next_up(a.lo_ * b.lo_)};
            }
            if (b.lo_ >= 0) return {next_down(a.lo_ * b.hi_), next_up(a.hi_ * b.hi_)};
            if (b.hi_ <= 0) return {next_down(a.hi_ * b.lo_), next_up(a.lo_ * b.lo_)};
            return {next_down(std::min(a.lo_ * b.hi_, a.hi_ * b.lo_)),
                    next_up(std::max(a.lo_ * b.lo_, a.hi_ * b.hi_))};
        }
        return unbounded_product(a, b);
    }
    // Division (paper section 2, remark 1): defined when 0 is not in b; otherwise
    // the result is the entire line (use divide_intersect for the extended form).
    friend Interval operator/(Interval a, Interval b) {
        if (b.lo_ <= 0 && b.hi_ >= 0) return entire();
        double q1 = a.lo_ / b.lo_, q2 = a.lo_ / b.hi_, q3 = a.hi_ / b.lo_, q4 = a.hi_ / b.hi_;
        if (std::isnan(q1 + q2 + q3 + q4)) return unbounded_quotient(a, b); // NaN or inf - inf
        double l = std::min(std::min(q1, q2), std::min(q3, q4));
        double h = std::max(std::max(q1, q2), std::max(q3, q4));
        return {next_down(l), next_up(h)};
    }
    Interval& operator+=(Interval b) { return *this = *this + b; }
    Interval& operator-=(Interval b) { return *this = *this - b; }
    Interval& operator*=(Interval b) { return *this = *this * b; }
    Interval& operator/=(Interval b) { return *this = *this / b; }

    friend std::ostream& operator<<(std::ostream& os, Interval a) {
        return os << '[' << a.lo_ << ", " << a.hi_ << ']';
    }

  private:
    // The product where a bound is infinite (or NaN): all four products of
    // bounds, where a zero bound times an infinite one counts as 0 (the
    // interval holds the real 0, and 0 times any real of the other is 0; an
    // infinite bound stands for arbitrarily large reals, not for a value).
    [[gnu::noinline]] static Interval unbounded_product(Interval a, Interval b) {
        if (std::isnan(a.lo_) || std::isnan(a.hi_) || std::isnan(b.lo_) || std::isnan(b.hi_))
            return entire();
        if (a.is_thin() && a.lo_ == 0) return Interval(0); // 0 * anything finite or not
        if (b.is_thin() && b.lo_ == 0) return Interval(0);
        auto times = [](double x, double y) { return x == 0 || y == 0 ? 0.0 : x * y; };
        double p1 = times(a.lo_, b.lo_), p2 = times(a.lo_, b.hi_), p3 = times(a.hi_, b.lo_),
               p4 = times(a.hi_, b.hi_);
        return {next_down(std::min(std::min(p1, p2), std::min(p3, p4))),
                next_up(std::max(std::max(p1, p2), std::max(p3, p4)))};
    }

    // The quotient where a bound is infinite (or NaN), 0 not in b: an inf / inf
    // corner is no value and is left out (the finite corners next to it already
    // reach 0 and infinity); std::fmin and fmax skip it where std::min would
    // return it or not depending on the order.
    [[gnu::noinline]] static Interval unbounded_quotient(Interval a, Interval b) {
        if (std::isnan(a.lo_) || std::isnan(a.hi_) || std::isnan(b.lo_) || std::isnan(b.hi_))
            return entire();
        double q1 = a.lo_ / b.lo_, q2 = a.lo_ / b.hi_, q3 = a.hi_ / b.lo_, q4 = a.hi_ / b.hi_;
        double l = std::fmin(std::fmin(q1, q2), std::fmin(q3, q4));
        double h = std::fmax(std::fmax(q1, q2), std::fmax(q3, q4));
        if (std::isnan(l) || std::isnan(h)) return entire(); // every corner inf / inf
        return {next_down(l), next_up(h)};
    }

    double lo_ = 0, hi_ = 0;
};

// Range of x^2 (tighter than x*x when 0 is in x).
inline Interval sqr(Interval a) {
    double l = a.lo(), h = a.hi();
    if (l >= 0) return {next_down(l * l), next_up(h * h)};
    if (h <= 0) return {next_down(h * h), next_up(l * l)};
    return {0.0, next_up(std::max(l * l, h * h))};
}
// Range of sqrt(x) over the non-negative part of x; empty if x < 0 entirely.
inline Interval sqrt(Interval a) {
    if (a.hi() < 0) return Interval::empty();
    double l = a.lo() <= 0 ? 0.0 : std::max(0.0, next_down(std::sqrt(a.lo())));
    return {l, next_up(std::sqrt(a.hi()))};
}
inline Interval abs(Interval a) {
    if (a.lo() >= 0) return a;
    if (a.hi() <= 0) return -a;
    return {0.0, std::max(-a.lo(), a.hi())};
}
// Interval hull of two intervals ([ ]S of the paper).
inline Interval hull(Interval a, Interval b) {
    if (a.is_empty()) return b;
    if (b.is_empty()) return a;
    return {std::min(a.lo(), b.lo()), std::max(a.hi(), b.hi())};
}
inline Interval intersect(Interval a, Interval b) {
    return {std::max(a.lo(), b.lo()), std::min(a.hi(), b.hi())};
}

// Hull of { q in x : q * d = n for some n in num, d in den }: the step of the
// Gauss-Seidel operator (Definition 5) with extended division when 0 is in den.
inline Interval divide_intersect(Interval num, Interval den, Interval x) {
    if (num.is_empty() || den.is_empty() || x.is_empty()) return Interval::empty();
    if (!den.contains(0.0)) return intersect(num / den, x);
    if (num.contains(0.0)) return x; // 0 = q * 0 for every q
    constexpr double inf = std::numeric_limits<double>::infinity();
    Interval left = Interval::empty(), right = Interval::empty();
    if (num.lo() > 0) {
        if (den.hi() > 0) right = {next_down(num.lo() / den.hi()), inf};
        if (den.lo() < 0) left = {-inf, next_up(num.lo() / den.lo())};
    } else { // num.hi() < 0
        if (den.hi() > 0) left = {-inf, next_up(num.hi() / den.hi())};
        if (den.lo() < 0) right = {next_down(num.hi() / den.lo()), inf};
    }
    return hull(intersect(left, x), intersect(right, x));
}

} // namespace seamless
