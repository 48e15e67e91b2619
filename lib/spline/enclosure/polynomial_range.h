// SPDX-License-Identifier: MIT
// Ranges of polynomials with interval coefficients over intervals (paper
// section 5, Lemma 2): one-dimensional ones, and the power form of a patch
// over a parameter box by nested Horner, ordered as sum_i b_i(t) s^i when [t]
// is the narrower interval and sum_j c_j(s) t^j otherwise. Outward rounded:
// a range never misses a value. The patch enclosures (enclosure.h) intersect
// these with the mean value form and the convex hull.
#pragma once

#include <seamless/interval/interval.h>
#include <seamless/spline/enclosure/power_form.h>

namespace seamless {

// A box of local parameters; a subset of [0,1]^2 for the patch enclosures.
struct ParamBox {
    Interval s{0.0, 1.0}, t{0.0, 1.0};
};

// Range of a one-dimensional polynomial sum_{i<=n} c_i u^i with interval
// coefficients over u: Lemma 2 when u >= 0 (the lower and upper coefficient
// polynomials bounded separately, each by Horner, mean value form or, where
// monotone, its end values), interval Horner otherwise.
Interval polynomial_range(const Interval* c, int n, Interval u);
// Coordinate c of a power form over a box by nested Horner (section 5 ordering).
Interval horner(const PowerForm& f, int c, ParamBox box);
// The same two with every degree a run-time loop bound: the reference for the
// unrolled fixed-degree paths (tests compare them bit for bit).
Interval polynomial_range_generic(const Interval* c, int n, Interval u);
Interval horner_generic(const PowerForm& f, int c, ParamBox box);

// Coordinate c of the derivative of f along s (dir 0) or t (dir 1) over a box,
// by horner() on the differentiated coefficients formed on the fly.
Interval horner_derivative(const PowerForm& f, int c, int dir, ParamBox box);

// Range enclosures (horner calls) made on this thread so far: a statistic
// for the renderer's --stats (differences around a piece of work).
long long range_enclosure_count();

} // namespace seamless
