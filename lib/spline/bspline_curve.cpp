// SPDX-License-Identifier: MIT
#include <seamless/spline/bspline_curve.h>

#include <algorithm>

namespace seamless {

CurvePoint evaluate(const BSplineCurve& c, double t) {
    const int p = c.degree;
    t = std::clamp(t, c.t_min(), c.t_max());
    const int k = find_span(p, c.size(), c.knots, t);
    double N[kMaxDegree + 1], dN[kMaxDegree + 1];
    basis_functions(p, k, c.knots, t, N, dN);
    HPoint X{0, 0, 0, 0}, Xt{0, 0, 0, 0};
    for (int a = 0; a <= p; ++a) {
        const int i = k - p + a;
        const HPoint h = HPoint::from(c.points[i], c.weight(i));
        X = X + N[a] * h;
        Xt = Xt + dN[a] * h;
    }
    // Quotient rule on the homogeneous coordinates, as for surfaces.
    CurvePoint r;
    r.point = X.xyz() / X.w;
    r.tangent = (Xt.xyz() - Xt.w * r.point) / X.w;
    return r;
}

Vec3 evaluate_point(const BSplineCurve& c, double t) {
    const int p = c.degree;
    t = std::clamp(t, c.t_min(), c.t_max());
    const int k = find_span(p, c.size(), c.knots, t);
    double N[kMaxDegree + 1];
    basis_functions(p, k, c.knots, t, N, nullptr);
    HPoint X{0, 0, 0, 0};
    for (int a = 0; a <= p; ++a) {
        const int i = k - p + a;
        X = X + N[a] * HPoint::from(c.points[i], c.weight(i));
    }
    return X.xyz() / X.w;
}

} // namespace seamless
