// SPDX-License-Identifier: MIT
// The small parts of error_bound.h: second derivative bounds, the rounding
// allowance, subpatch extraction (the bounds: fan_bound.cpp,
// certified_fan_bound.cpp).
#include <seamless/tessellate/bounds/error_bound.h>
#include <seamless/tessellate/bounds/net_bounds.h>

#include <limits>

namespace seamless {
namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();
} // namespace

std::array<double, 2> second_derivative_bounds(const BezierPatch& b) {
    const DerivativeBounds d = derivative_bounds(net_of(b, b.corner(0)));
    return {d.A, d.C};
}

double rounding_allowance(int depth, double scale) {
    return (8.0 * (depth + 8)) * kEps * scale;
}

BezierPatch extract_subpatch(const BezierPatch& patch, const ParamRect& r) {
    return extract_box(patch, param_of(r.s0), param_of(r.s1), param_of(r.t0), param_of(r.t1));
}

BezierPatch extract_box(const BezierPatch& patch, double s0, double s1, double t0, double t1) {
    BezierPatch cur = patch, lo, hi;
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

} // namespace seamless
