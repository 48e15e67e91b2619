// SPDX-License-Identifier: MIT
#include <seamless/spline/bspline_surface.h>

#include <algorithm>

namespace seamless {

int find_span(int degree, int n, const std::vector<double>& knots, double t) {
    // The last knot at or below t among t_(p+1) .. t_(n-1), by bisection
    // (curves carried through parameter maps have thousands of spans), then
    // down past empty spans at the top.
    const auto first = knots.begin() + degree + 1, last = knots.begin() + n;
    int k = static_cast<int>(std::upper_bound(first, last, t) - knots.begin()) - 1;
    while (k > degree && !(knots[k] < knots[k + 1])) --k;
    return k;
}

void basis_functions(int p, int k, const std::vector<double>& U, double t, double* N0, double* N1) {
    // Triangular table of the Cox-de Boor recurrence (The NURBS Book, A2.2/A2.3, first derivative).
    double left[kMaxDegree + 2], right[kMaxDegree + 2];
    double ndu[kMaxDegree + 1][kMaxDegree + 1];
    ndu[0][0] = 1.0;
    for (int j = 1; j <= p; ++j) {
        left[j] = t - U[k + 1 - j];
        right[j] = U[k + j] - t;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            ndu[j][r] = right[r + 1] + left[j - r]; // lower triangle: knot differences
            double temp = ndu[r][j - 1] / ndu[j][r];
            ndu[r][j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    for (int r = 0; r <= p; ++r) N0[r] = ndu[r][p];
    if (!N1) return;
    if (p == 0) {
        N1[0] = 0;
        return;
    }
    // N'_{k-p+r,p} = p * (N_{k-p+r,p-1} / (U[k+r]-U[k-p+r])
    //                     - N_{k-p+r+1,p-1} / (U[k+r+1]-U[k-p+r+1]))
    for (int r = 0; r <= p; ++r) {
        double d = 0.0;
        if (r >= 1) d += ndu[r - 1][p - 1] / ndu[p][r - 1];
        if (r <= p - 1) d -= ndu[r][p - 1] / ndu[p][r];
        N1[r] = p * d;
    }
}

namespace {

// (u, v) clamped to the domain and the knot spans holding them.
struct Spans {
    double u, v;
    int ku, kv;
};
Spans spans(const BSplineSurface& s, double u, double v) {
    u = std::clamp(u, s.u_min(), s.u_max());
    v = std::clamp(v, s.v_min(), s.v_max());
    return {u, v, find_span(s.degree_u, s.size_u, s.knots_u, u),
            find_span(s.degree_v, s.size_v, s.knots_v, v)};
}

} // namespace

SurfacePoint evaluate(const BSplineSurface& s, double u_in, double v_in) {
    const int p = s.degree_u, q = s.degree_v;
    const auto [u, v, ku, kv] = spans(s, u_in, v_in);
    double Nu[kMaxDegree + 1], dNu[kMaxDegree + 1], Nv[kMaxDegree + 1], dNv[kMaxDegree + 1];
    basis_functions(p, ku, s.knots_u, u, Nu, dNu);
    basis_functions(q, kv, s.knots_v, v, Nv, dNv);
    HPoint X{0, 0, 0, 0}, Xu{0, 0, 0, 0}, Xv{0, 0, 0, 0};
    for (int a = 0; a <= p; ++a) {
        HPoint row{0, 0, 0, 0}, rowv{0, 0, 0, 0};
        for (int b = 0; b <= q; ++b) {
            HPoint c = s.hpoint(ku - p + a, kv - q + b);
            row = row + Nv[b] * c;
            rowv = rowv + dNv[b] * c;
        }
        X = X + Nu[a] * row;
        Xu = Xu + dNu[a] * row;
        Xv = Xv + Nu[a] * rowv;
    }
    // Quotient rule on the homogeneous coordinates: P = X/W, P_u = (X_u - P W_u) / W.
    SurfacePoint r;
    r.point = X.xyz() / X.w;
    r.du = (Xu.xyz() - Xu.w * r.point) / X.w;
    r.dv = (Xv.xyz() - Xv.w * r.point) / X.w;
    return r;
}

Vec3 evaluate_point(const BSplineSurface& s, double u_in, double v_in) {
    const int p = s.degree_u, q = s.degree_v;
    const auto [u, v, ku, kv] = spans(s, u_in, v_in);
    double Nu[kMaxDegree + 1], Nv[kMaxDegree + 1];
    basis_functions(p, ku, s.knots_u, u, Nu, nullptr);
    basis_functions(q, kv, s.knots_v, v, Nv, nullptr);
    HPoint X{0, 0, 0, 0};
    for (int a = 0; a <= p; ++a) {
        HPoint row{0, 0, 0, 0};
        for (int b = 0; b <= q; ++b) row = row + Nv[b] * s.hpoint(ku - p + a, kv - q + b);
        X = X + Nu[a] * row;
    }
    return X.xyz() / X.w;
}

Box3 control_box(const BSplineSurface& s) {
    Box3 b;
    for (Vec3 p : s.points) b.extend(p);
    return b;
}

} // namespace seamless
