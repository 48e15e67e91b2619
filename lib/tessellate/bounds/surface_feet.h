// SPDX-License-Identifier: MIT
// The surface the fan bounds evaluate and the Gauss-Newton feet of their
// map phi (error_bound.h: the construction; fan_bound.cpp: the four-triangle
// bound of the subdivision; certified_fan_bound.cpp: the bound of the final
// fans, with fan_phi.h). Internal to those files.
#pragma once

#include <seamless/spline/bezier_patch.h>
#include <seamless/spline/fixed_degree.h>
#include <seamless/tessellate/bounds/power_basis.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless::feet {

inline constexpr double kEps = std::numeric_limits<double>::epsilon();

struct Param {
    double s = 0, t = 0;
};

inline SurfacePoint surface_point(const BezierPatch& b, double s, double t) {
    if (b.p == 3 && b.q == 3)
        return b.rational ? evaluate_fixed<3, 3, true>(b, s, t)
                          : evaluate_fixed<3, 3, false>(b, s, t);
    return evaluate(b, s, t);
}

// The surface a bound evaluates: a polynomial bicubic patch in the power basis
// (power_basis.h: a third of the instructions, within `error` of the surface),
// any other one by surface_point.
struct Surface {
    const BezierPatch& patch;
    const PowerBasisPatch* pb = nullptr; // null: by surface_point
    PowerBasisPatch own;
    // `given`: patch's power basis, already at hand.
    explicit Surface(const BezierPatch& b, const PowerBasisPatch* given = nullptr) : patch(b) {
        if (given) {
            pb = given;
        } else if (has_power_basis(b)) {
            own = power_basis(b);
            pb = &own;
        }
    }
    Surface(const Surface&) = delete;
    Surface& operator=(const Surface&) = delete;
    SurfacePoint at(double s, double t) const {
        return pb ? evaluate(*pb, s, t) : surface_point(patch, s, t);
    }
    // The same point without the derivatives.
    Vec3 point(double s, double t) const {
        return pb ? evaluate_point(*pb, s, t) : surface_point(patch, s, t).point;
    }
    // Bound on the evaluation's rounding beyond rounding_allowance's.
    double error() const { return pb ? pb->error : 0; }
};

// One Gauss-Newton step from u (sp = S and its derivatives there) toward the
// foot of x on S, each coordinate's step at most `limit` (near a pole the foot
// is ill-determined), kept only when it brings S closer to x; clamped to
// [0,1]^2. Returns whether it moved; u and sp follow (sp's derivatives only
// when `derivatives`, for a further step: the trial point alone otherwise, the
// same value as evaluate's point, power_basis.h). No step (and no
// evaluation) once the residual's tangential part is below kConverged of the
// residual: the bound counts that part (|g_i - (n.g_i) n|), so it stays within
// kConverged^2 / 2 of its value at the exact foot, a fraction of a percent.
inline constexpr double kConverged = 0.02;
[[gnu::always_inline]] inline bool foot_step(const Surface& b, Vec3 x, Param& u, SurfacePoint& sp,
                                             double limit, bool derivatives) {
    const Vec3 r = x - sp.point;
    const double a11 = dot(sp.du, sp.du), a22 = dot(sp.dv, sp.dv), a12 = dot(sp.du, sp.dv);
    const double reg = 1e-12 * (a11 + a22);
    const double g1 = dot(sp.du, r), g2 = dot(sp.dv, r);
    const double det = (a11 + reg) * (a22 + reg) - a12 * a12;
    if (!(det > 0) || !std::isfinite(det) || !(limit > 0)) return false;
    const double ds = ((a22 + reg) * g1 - a12 * g2) / det, dt = ((a11 + reg) * g2 - a12 * g1) / det;
    if (!std::isfinite(ds) || !std::isfinite(dt)) return false;
    // ds g1 + dt g2: the squared length of r's projection on the tangent plane.
    if (ds * g1 + dt * g2 <= kConverged * kConverged * dot(r, r)) return false;
    const Param v{std::clamp(u.s + std::clamp(ds, -limit, limit), 0.0, 1.0),
                  std::clamp(u.t + std::clamp(dt, -limit, limit), 0.0, 1.0)};
    if (v.s == u.s && v.t == u.t) return false;
    SurfacePoint sv;
    if (derivatives)
        sv = b.at(v.s, v.t);
    else
        sv.point = b.point(v.s, v.t);
    const Vec3 gv = sv.point - x;
    if (!(dot(gv, gv) < dot(r, r))) return false;
    u = v;
    sp = sv;
    return true;
}

inline Param foot(const Surface& b, Vec3 x, Param u, double limit, Vec3& g) {
    SurfacePoint sp = b.at(u.s, u.t);
    foot_step(b, x, u, sp, limit, false);
    g = sp.point - x;
    return u;
}

// A line in the parameters, u(tau) = c0 + tau (c1 - c0) for tau in [lo, hi].
struct ParamLine {
    Param c0, c1;
    double lo = 0, hi = 1;
};

// Same as foot along `line`, from u(tau).
inline double foot_on_line(const Surface& b, Vec3 x, const ParamLine& line, double tau,
                           double limit, Vec3& g) {
    const Param c0 = line.c0, c1 = line.c1;
    const double lo = line.lo, hi = line.hi;
    auto at = [&](double z) { return Param{c0.s + z * (c1.s - c0.s), c0.t + z * (c1.t - c0.t)}; };
    tau = std::clamp(tau, lo, hi);
    const Param u = at(tau);
    const SurfacePoint sp = b.at(u.s, u.t);
    g = sp.point - x;
    const Vec3 d = (c1.s - c0.s) * sp.du + (c1.t - c0.t) * sp.dv;
    const double dd = dot(d, d);
    if (!(dd > 0) || !std::isfinite(dd)) return tau;
    const double step = dot(d, x - sp.point) / dd;
    if (!std::isfinite(step)) return tau;
    const double z = std::clamp(tau + std::clamp(step, -limit, limit), lo, hi);
    const Param v = at(z);
    const Vec3 gv = b.point(v.s, v.t) - x;
    if (!(dot(gv, gv) < dot(g, g))) return tau;
    g = gv;
    return z;
}

// Up to `iterations` steps toward the foot, the total move at most `limit`
// per coordinate.
inline Param foot_iterated(const Surface& b, Vec3 x, Param w, double limit, int iterations,
                           Vec3& g) {
    if (iterations == 0) {
        g = b.point(w.s, w.t) - x;
        return w;
    }
    Param u = w;
    SurfacePoint sp = b.at(u.s, u.t);
    for (int it = 0; it < iterations; ++it) {
        const double left = limit - std::max(std::abs(u.s - w.s), std::abs(u.t - w.t));
        if (!foot_step(b, x, u, sp, left, it + 1 < iterations)) break;
    }
    g = sp.point - x;
    return u;
}

inline constexpr Param kCorner[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
inline constexpr Param kCentre{0.5, 0.5};

// A refined vertex: its parameter under phi and g = S(phi(w)) - F(w).
struct Node {
    Param u;
    Vec3 g;
};

} // namespace seamless::feet
