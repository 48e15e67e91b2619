// SPDX-License-Identifier: MIT
#include <seamless/spline/bernstein_horner.h>
#include <seamless/spline/bezier_patch.h>
#include <seamless/spline/span_segments.h>

#include <algorithm>

namespace seamless {

const SpanSegments::Segment& SpanSegments::segment(int k) {
    if (k == last_k_) return *last_;
    const auto [it, fresh] = index_.try_emplace(k, static_cast<int>(segments_.size()));
    if (fresh) {
        // Bezier point i of span [t_k, t_k+1] is the blossom at (t_k
        // p - i times, t_k+1 i times): de Boor's triangle with the level's
        // own argument (The NURBS Book, section 5.2, by blossoming).
        const BSplineCurve& c = *c_;
        const std::vector<double>& U = c.knots;
        const int p = c.degree;
        Segment s;
        s.t0 = U[k], s.t1 = U[k + 1];
        for (int i = 0; i <= p; ++i) {
            std::array<HPoint, kMaxDegree + 1> d;
            for (int j = 0; j <= p; ++j)
                d[j] = HPoint::from(c.points[k - p + j], c.weight(k - p + j));
            for (int r = 1; r <= p; ++r) {
                const double u = r <= p - i ? s.t0 : s.t1;
                for (int j = p; j >= r; --j) {
                    const double a = (u - U[k - p + j]) / (U[j + 1 + k - r] - U[k - p + j]);
                    d[j] = (1 - a) * d[j - 1] + a * d[j];
                }
            }
            s.cp[i] = d[p];
        }
        double b[kMaxDegree + 1];
        binomials(p, b);
        for (int i = 0; i <= p; ++i) s.scaled[i] = b[i] * s.cp[i];
        segments_.push_back(s);
    }
    last_k_ = k, last_ = &segments_[it->second];
    return *last_;
}

const SpanSegments::Segment& SpanSegments::segment_at(double& t) {
    const BSplineCurve& c = *c_;
    t = std::clamp(t, c.t_min(), c.t_max());
    // Samples come in runs over one span: find_span's [t_k, t_k+1) there.
    if (last_ && t >= last_->t0 && t < last_->t1) return *last_;
    return segment(find_span(c.degree, c.size(), c.knots, t));
}

Vec3 SpanSegments::point(double t) {
    const Segment& s = segment_at(t);
    const int p = c_->degree;
    const HPoint X = bernstein_horner(s.scaled.data(), p, HornerRatio((t - s.t0) / (s.t1 - s.t0)));
    return X.xyz() / X.w;
}

Vec3 SpanSegments::tangent(double t) {
    const Segment& s = segment_at(t);
    const int p = c_->degree;
    const double h = s.t1 - s.t0;
    double B[kMaxDegree + 1], dB[kMaxDegree + 1];
    bernstein(p, (t - s.t0) / h, B, dB);
    HPoint X{0, 0, 0, 0}, dX{0, 0, 0, 0};
    for (int i = 0; i <= p; ++i) X = X + B[i] * s.cp[i], dX = dX + dB[i] * s.cp[i];
    // (x / w)' = (x' - (x / w) w') / w, and d/dt = d/ds / h.
    return (dX.xyz() - (X.xyz() / X.w) * dX.w) / (X.w * h);
}

} // namespace seamless
