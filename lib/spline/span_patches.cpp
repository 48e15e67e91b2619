// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/spline/bernstein_horner.h>
#include <seamless/spline/knot_insertion.h>
#include <seamless/spline/span_patches.h>

#include <algorithm>

namespace seamless {

const SpanPatches::Span& SpanPatches::span(int ku, int kv) {
    if (ku == last_ku_ && kv == last_kv_) return *last_;
    const std::int64_t key = static_cast<std::int64_t>(ku) << 32 | static_cast<std::uint32_t>(kv);
    const auto [it, fresh] = index_.try_emplace(key, static_cast<int>(spans_.size()));
    if (fresh) {
        // The span's (p+1) x (q+1) control points with the 2p + 2 and 2q + 2
        // knots around it: a surface of one span, the same there.
        const BSplineSurface& s = *s_;
        const int p = s.degree_u, q = s.degree_v;
        BSplineSurface one;
        one.degree_u = p, one.degree_v = q, one.size_u = p + 1, one.size_v = q + 1;
        one.knots_u.assign(s.knots_u.begin() + (ku - p), s.knots_u.begin() + (ku + p + 2));
        one.knots_v.assign(s.knots_v.begin() + (kv - q), s.knots_v.begin() + (kv + q + 2));
        for (int i = 0; i <= p; ++i)
            for (int j = 0; j <= q; ++j) {
                one.points.push_back(s.point(ku - p + i, kv - q + j));
                if (s.rational()) one.weights.push_back(s.weight(ku - p + i, kv - q + j));
            }
        std::vector<BezierPatch> b = bezier_patches(one, -1);
        SEAMLESS_CHECK(b.size() == 1, "a non-empty knot span is one Bezier patch");
        Span& added = spans_.emplace_back();
        added.patch = b[0];
        if (std::max(p, q) > 3) {
            BezierPatch& c = scaled_.emplace_back(b[0]);
            double bu[BezierPatch::kMaxOrder], bv[BezierPatch::kMaxOrder];
            binomials(p, bu);
            binomials(q, bv);
            for (int i = 0; i <= p; ++i)
                for (int j = 0; j <= q; ++j) c.at(i, j) = (bu[i] * bv[j]) * c.at(i, j);
            added.scaled = &c;
        }
    }
    last_ku_ = ku, last_kv_ = kv, last_ = &spans_[it->second];
    return *last_;
}

const SpanPatches::Span& SpanPatches::span_at(double& u, double& v) {
    const BSplineSurface& s = *s_;
    u = std::clamp(u, s.u_min(), s.u_max());
    v = std::clamp(v, s.v_min(), s.v_max());
    // Samples come in runs over one span: find_span's [t_k, t_k+1) there.
    if (last_) {
        const BezierPatch& b = last_->patch;
        if (u >= b.u0 && u < b.u1 && v >= b.v0 && v < b.v1) return *last_;
    }
    return span(find_span(s.degree_u, s.size_u, s.knots_u, u),
                find_span(s.degree_v, s.size_v, s.knots_v, v));
}

Vec3 SpanPatches::point(double u, double v) {
    const Span& sp = span_at(u, v);
    const BezierPatch& b = sp.patch;
    const double x = (u - b.u0) / (b.u1 - b.u0), y = (v - b.v0) / (b.v1 - b.v0);
    if (!sp.scaled) return evaluate_point(b, x, y);
    HPoint rows[BezierPatch::kMaxOrder];
    const HornerRatio hy(y);
    for (int i = 0; i <= b.p; ++i) rows[i] = bernstein_horner(&sp.scaled->at(i, 0), b.q, hy);
    const HPoint X = bernstein_horner(rows, b.p, HornerRatio(x));
    return X.xyz() / X.w;
}

SurfacePoint SpanPatches::at(double u, double v) {
    const BezierPatch& b = span_at(u, v).patch;
    const double hu = b.u1 - b.u0, hv = b.v1 - b.v0;
    SurfacePoint p = evaluate(b, (u - b.u0) / hu, (v - b.v0) / hv);
    p.du = p.du / hu;
    p.dv = p.dv / hv;
    return p;
}

} // namespace seamless
