// SPDX-License-Identifier: MIT
#include <seamless/mesh/deviation/spline_projection.h>

#include <algorithm>
#include <cmath>

namespace seamless {

SurfaceProjection project_to_surface(const BSplineSurface& b, Vec3 x, double u, double v,
                                     int iterations) {
    const double u0 = b.u_min(), u1 = b.u_max(), v0 = b.v_min(), v1 = b.v_max();
    double s = std::clamp(u, u0, u1), t = std::clamp(v, v0, v1);
    SurfacePoint sp = evaluate(b, s, t);
    double best = distance(sp.point, x);
    for (int it = 0; it < iterations && best > 0; ++it) {
        const Vec3 r = sp.point - x;
        // Levenberg regularisation keeps the step finite at poles and folds.
        const double reg = 1e-12 * (dot(sp.du, sp.du) + dot(sp.dv, sp.dv));
        const double a11 = dot(sp.du, sp.du) + reg, a22 = dot(sp.dv, sp.dv) + reg;
        const double a12 = dot(sp.du, sp.dv);
        const double g1 = dot(sp.du, r), g2 = dot(sp.dv, r);
        const double det = a11 * a22 - a12 * a12;
        if (!(det > 0)) break;
        double ds = -(a22 * g1 - a12 * g2) / det, dt = -(a11 * g2 - a12 * g1) / det;
        bool improved = false;
        for (int halving = 0; halving < 6 && !improved; ++halving) {
            const double ns = std::clamp(s + ds, u0, u1), nt = std::clamp(t + dt, v0, v1);
            const SurfacePoint np = evaluate(b, ns, nt);
            const double d = distance(np.point, x);
            if (d < best) {
                improved = true;
                best = d;
                s = ns;
                t = nt;
                sp = np;
            }
            ds *= 0.5;
            dt *= 0.5;
        }
        if (!improved || std::max(std::abs(ds) / (u1 - u0), std::abs(dt) / (v1 - v0)) < 1e-15)
            break;
    }
    return {best, s, t};
}

CurveProjection project_to_curve(const BSplineCurve& c, Vec3 x, double t, double t0, double t1,
                                 int iterations) {
    double s = std::clamp(t, t0, t1);
    CurvePoint cp = evaluate(c, s);
    double best = distance(cp.point, x);
    for (int it = 0; it < iterations && best > 0; ++it) {
        const double a = dot(cp.tangent, cp.tangent);
        if (!(a > 0)) break;
        double ds = -dot(cp.tangent, cp.point - x) / a;
        bool improved = false;
        for (int halving = 0; halving < 6 && !improved; ++halving) {
            const double ns = std::clamp(s + ds, t0, t1);
            const CurvePoint np = evaluate(c, ns);
            const double d = distance(np.point, x);
            if (d < best) {
                improved = true;
                best = d;
                s = ns;
                cp = np;
            }
            ds *= 0.5;
        }
        if (!improved || std::abs(ds) < 1e-15 * (t1 - t0)) break;
    }
    return {best, s};
}

} // namespace seamless
