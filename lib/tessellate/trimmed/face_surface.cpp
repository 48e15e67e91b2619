// SPDX-License-Identifier: MIT
#include <seamless/tessellate/trimmed/face_surface.h>

#include <algorithm>
#include <cmath>

namespace seamless {

namespace {

// t in [lo, hi]: as is; else moved by whole periods hi - lo into it.
double wrap(double t, double lo, double hi) {
    if (t >= lo && t <= hi) return t;
    const double period = hi - lo;
    return lo + (t - lo - period * std::floor((t - lo) / period));
}

// The interior knots of multiplicity >= degree.
std::vector<double> creases(const std::vector<double>& knots, int degree, int size) {
    std::vector<double> out;
    for (int i = degree + 1; i < size;) {
        int j = i;
        while (j < size && knots[j] == knots[i]) ++j;
        if (j - i >= degree) out.push_back(knots[i]);
        i = j;
    }
    return out;
}

bool crosses(const std::vector<double>& creases, bool closed, double lo, double hi, double a,
             double b, double c) {
    const double from = std::min({a, b, c}), to = std::max({a, b, c});
    const double period = hi - lo;
    for (double k : creases)
        for (int shift = closed ? -1 : 0; shift <= (closed ? 1 : 0); ++shift)
            if (k + shift * period >= from && k + shift * period <= to) return true;
    return false;
}

} // namespace

bool FaceSurface::crosses_crease(const std::array<Vec3, 3>& uv) const {
    return crosses(creases_u_, closed_u_, s_->u_min(), s_->u_max(), uv[0].x, uv[1].x, uv[2].x) ||
           crosses(creases_v_, closed_v_, s_->v_min(), s_->v_max(), uv[0].y, uv[1].y, uv[2].y);
}

FaceSurface::FaceSurface(const BSplineSurface& s)
    : s_(&s), creases_u_(creases(s.knots_u, s.degree_u, s.size_u)),
      creases_v_(creases(s.knots_v, s.degree_v, s.size_v)) {
    const double tiny = 1e-12 * control_box(s).max_extent();
    closed_u_ = closed_v_ = true;
    for (int j = 0; j < s.size_v; ++j)
        closed_u_ = closed_u_ && distance(s.point(0, j), s.point(s.size_u - 1, j)) <= tiny;
    for (int i = 0; i < s.size_u; ++i)
        closed_v_ = closed_v_ && distance(s.point(i, 0), s.point(i, s.size_v - 1)) <= tiny;
    const bool bilinear = s.degree_u == 1 && s.degree_v == 1 && s.size_u == 2 && s.size_v == 2;
    affine_ = bilinear &&
              (!s.rational() || std::all_of(s.weights.begin(), s.weights.end(),
                                            [&](double w) { return w == s.weights[0]; })) &&
              norm(s.point(0, 0) + s.point(1, 1) - s.point(1, 0) - s.point(0, 1)) <= tiny;
}

Vec3 FaceSurface::wrapped(Vec3 uv) const {
    return {closed_u_ ? wrap(uv.x, s_->u_min(), s_->u_max()) : uv.x,
            closed_v_ ? wrap(uv.y, s_->v_min(), s_->v_max()) : uv.y, 0};
}

Vec3 FaceSurface::point(Vec3 uv) const {
    const Vec3 w = wrapped(uv);
    if (w.x < s_->u_min() || w.x > s_->u_max() || w.y < s_->v_min() || w.y > s_->v_max())
        return at(uv).point; // the continuation needs the derivatives
    return evaluate_point(*s_, w.x, w.y);
}

Vec3 FaceSurface::point(Vec3 uv, SpanPatches& spans) const {
    const Vec3 w = wrapped(uv);
    if (w.x < s_->u_min() || w.x > s_->u_max() || w.y < s_->v_min() || w.y > s_->v_max())
        return at(uv).point;
    return spans.point(w.x, w.y);
}

namespace {

// The surface point at uv, by `eval` at uv clamped to the domain: beyond
// it, to first order (exact for planes, and close for pcurves a little
// outside it, within the file's tolerance).
template <class Eval> SurfacePoint continued(const BSplineSurface& s, Vec3 w, Eval&& eval) {
    const double u = w.x, v = w.y;
    const double uc = std::clamp(u, s.u_min(), s.u_max()), vc = std::clamp(v, s.v_min(), s.v_max());
    SurfacePoint p = eval(uc, vc);
    if (uc != u || vc != v) p.point += (u - uc) * p.du + (v - vc) * p.dv;
    return p;
}

} // namespace

SurfacePoint FaceSurface::at(Vec3 uv) const {
    return continued(*s_, wrapped(uv), [&](double u, double v) { return evaluate(*s_, u, v); });
}

SurfacePoint FaceSurface::at(Vec3 uv, SpanPatches& spans) const {
    return continued(*s_, wrapped(uv), [&](double u, double v) { return spans.at(u, v); });
}

double distance_to_surface(const FaceSurface& s, SpanPatches& spans, Vec3 q, Vec3 uv,
                           double enough) {
    SurfacePoint p = s.at(uv, spans);
    double best = distance(p.point, q);
    for (int it = 0; it < 4 && best > enough; ++it) {
        const Vec3 r = q - p.point;
        const double a = dot(p.du, p.du), b = dot(p.du, p.dv), c = dot(p.dv, p.dv);
        const double damp = 1e-9 * (a + c), ru = dot(r, p.du), rv = dot(r, p.dv);
        const double det = (a + damp) * (c + damp) - b * b;
        if (!(det > 0)) break;
        uv = uv + Vec3{((c + damp) * ru - b * rv) / det, ((a + damp) * rv - b * ru) / det, 0};
        p = s.at(uv, spans);
        best = std::min(best, distance(p.point, q));
    }
    return best;
}

} // namespace seamless
