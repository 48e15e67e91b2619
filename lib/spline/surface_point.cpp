// SPDX-License-Identifier: MIT
#include <seamless/spline/surface_point.h>

#include <seamless/spline/bezier_patch.h>

#include <algorithm>
#include <cmath>

namespace seamless {

namespace {

// The normal n = sp.normal() is used as it is (not approached from elsewhere).
// Besides a vanishing cross product, a derivative 1e-10 of the other's is a
// pole whose control points differ by rounding (a sphere placed off its
// axes): its direction is noise.
bool regular(const SurfacePoint& sp, Vec3 n) {
    const double du = norm(sp.du), dv = norm(sp.dv);
    return is_finite(n) && norm(n) > 1e-12 * du * dv && norm(n) > 0 &&
           std::min(du, dv) > 1e-10 * std::max(du, dv);
}

} // namespace

bool regular_unit_normal(const BezierPatch& b, double s, double t, Vec3& n) {
    const SurfacePoint sp = evaluate(b, s, t);
    const Vec3 m = sp.normal();
    if (!regular(sp, m)) return false;
    n = normalize(m);
    return true;
}

Vec3 unit_normal(const BezierPatch& b, double s, double t, double toward_s, double toward_t) {
    SurfacePoint sp = evaluate(b, s, t);
    Vec3 n = sp.normal();
    for (double d : {1e-7, 1e-5, 1e-3, 1e-1, 0.5}) {
        if (regular(sp, n)) break;
        sp = evaluate(b, s + d * (toward_s - s), t + d * (toward_t - t));
        n = sp.normal();
    }
    return normalize(n);
}

} // namespace seamless
