// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/spline/knot_insertion.h>
#include <seamless/spline/span_patches.h>

#include <algorithm>

namespace seamless {

const BezierPatch& SpanPatches::patch(int ku, int kv) {
    if (ku == last_ku_ && kv == last_kv_) return *last_;
    const std::int64_t key = static_cast<std::int64_t>(ku) << 32 | static_cast<std::uint32_t>(kv);
    const auto [it, fresh] = index_.try_emplace(key, static_cast<int>(patches_.size()));
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
        patches_.push_back(b[0]);
    }
    last_ku_ = ku, last_kv_ = kv, last_ = &patches_[it->second];
    return *last_;
}

Vec3 SpanPatches::point(double u, double v) {
    const BSplineSurface& s = *s_;
    u = std::clamp(u, s.u_min(), s.u_max());
    v = std::clamp(v, s.v_min(), s.v_max());
    const BezierPatch& b = patch(find_span(s.degree_u, s.size_u, s.knots_u, u),
                                 find_span(s.degree_v, s.size_v, s.knots_v, v));
    return evaluate_point(b, (u - b.u0) / (b.u1 - b.u0), (v - b.v0) / (b.v1 - b.v0));
}

} // namespace seamless
