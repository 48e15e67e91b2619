// SPDX-License-Identifier: MIT
#include <seamless/mesh/deviation/face_region.h>

#include <algorithm>
#include <cmath>

namespace seamless {
namespace {

// The surface's period in u (along_u) or v: its domain's width where the two
// opposite boundary curves coincide (within 1e-9 of its control box), else 0.
double period(const BSplineSurface& s, bool along_u) {
    const double tol = 1e-9 * norm(control_box(s).extent());
    constexpr int kProbes = 7;
    for (int i = 0; i < kProbes; ++i) {
        const double f = (i + 0.5) / kProbes;
        const Vec3 a = along_u
                           ? evaluate(s, s.u_min(), s.v_min() + f * (s.v_max() - s.v_min())).point
                           : evaluate(s, s.u_min() + f * (s.u_max() - s.u_min()), s.v_min()).point;
        const Vec3 b = along_u
                           ? evaluate(s, s.u_max(), s.v_min() + f * (s.v_max() - s.v_min())).point
                           : evaluate(s, s.u_min() + f * (s.u_max() - s.u_min()), s.v_max()).point;
        if (!(distance(a, b) <= tol)) return 0;
    }
    return along_u ? s.u_max() - s.u_min() : s.v_max() - s.v_min();
}

} // namespace

double FaceRegion::segment_distance(const Segment& s, double u, double v) {
    const double du = s.ub - s.ua, dv = s.vb - s.va;
    const double len2 = du * du + dv * dv;
    const double f =
        len2 > 0 ? std::clamp(((u - s.ua) * du + (v - s.va) * dv) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(u - (s.ua + f * du), v - (s.va + f * dv));
}

double curve_length(const BSplineCurve& c, double t0, double t1, int n) {
    double length = 0;
    Vec3 prev = evaluate(c, t0).point;
    for (int i = 1; i <= n; ++i) {
        const Vec3 p = evaluate(c, t0 + (t1 - t0) * i / n).point;
        length += distance(prev, p);
        prev = p;
    }
    return length;
}

FaceRegion::FaceRegion(const Model& model, int face, const FaceRegionOptions& options) {
    const BRep& brep = model.brep;
    const BRepFace& f = brep.faces[face];
    const BSplineSurface& surface = model.surfaces[f.surface];
    du_min_ = surface.u_min();
    du_max_ = surface.u_max();
    dv_min_ = surface.v_min();
    dv_max_ = surface.v_max();
    period_u_ = period(surface, true);
    period_v_ = period(surface, false);
    u0_ = v0_ = HUGE_VAL;
    u1_ = v1_ = -HUGE_VAL;
    if (f.loops.empty()) // no boundary given: the whole surface
        add_loop({du_min_, dv_min_, du_max_, dv_min_, du_max_, dv_max_, du_min_, dv_max_});
    for (const BRepLoop& loop : f.loops) {
        std::vector<double> uv;
        for (const BRepCoedge& ce : loop.coedges) {
            if (ce.pcurve < 0 || ce.edge < 0) continue; // validate_brep's to refuse, not ours
            const BRepEdge& e = brep.edges[ce.edge];
            const BSplineCurve& pc = brep.pcurves[ce.pcurve];
            int n = options.samples_per_coedge;
            if (options.spacing > 0 && !e.degenerate()) {
                const double length = curve_length(brep.curves[e.curve], e.t0, e.t1, 32);
                n = std::max(n,
                             static_cast<int>(std::min(1e9, std::ceil(length / options.spacing))));
            }
            n = std::clamp(n, 1, options.max_samples_per_coedge);
            for (int i = 0; i <= n; ++i) {
                const double w = static_cast<double>(ce.reversed ? n - i : i) / n;
                const Vec3 p = evaluate(pc, e.t0 + w * (e.t1 - e.t0)).point;
                const size_t m = uv.size();
                if (m >= 2 && uv[m - 2] == p.x && uv[m - 1] == p.y) continue;
                uv.push_back(p.x);
                uv.push_back(p.y);
            }
        }
        add_loop(uv);
    }
    bucket();
}

void FaceRegion::add_loop(const std::vector<double>& uv) {
    const size_t n = uv.size() / 2;
    for (size_t i = 0; i < n; ++i) {
        const size_t j = (i + 1) % n;
        u0_ = std::min(u0_, uv[2 * i]);
        u1_ = std::max(u1_, uv[2 * i]);
        v0_ = std::min(v0_, uv[2 * i + 1]);
        v1_ = std::max(v1_, uv[2 * i + 1]);
        if (n >= 2) segments_.push_back({uv[2 * i], uv[2 * i + 1], uv[2 * j], uv[2 * j + 1]});
    }
}

void FaceRegion::bucket() {
    if (segments_.empty()) {
        u0_ = v0_ = u1_ = v1_ = 0;
        strip_start_.assign(2, 0);
        return;
    }
    const int strips = std::clamp(static_cast<int>(std::sqrt(double(segments_.size()))), 1, 4096);
    strip_height_ = std::max((v1_ - v0_) / strips, 1e-300);
    auto strip_of = [&](double v) {
        return std::clamp(static_cast<int>(std::floor((v - v0_) / strip_height_)), 0, strips - 1);
    };
    std::vector<int> count(strips + 1, 0);
    for (const Segment& s : segments_)
        for (int k = strip_of(std::min(s.va, s.vb)); k <= strip_of(std::max(s.va, s.vb)); ++k)
            ++count[k + 1];
    for (int k = 0; k < strips; ++k) count[k + 1] += count[k];
    strip_start_ = count;
    strip_segments_.resize(count[strips]);
    for (int i = 0; i < static_cast<int>(segments_.size()); ++i) {
        const Segment& s = segments_[i];
        for (int k = strip_of(std::min(s.va, s.vb)); k <= strip_of(std::max(s.va, s.vb)); ++k)
            strip_segments_[count[k]++] = i;
    }
}

bool FaceRegion::contains_unshifted(double u, double v) const {
    if (!(u >= u0_ && u <= u1_ && v >= v0_ && v <= v1_)) return false;
    const int strips = static_cast<int>(strip_start_.size()) - 1;
    const int k =
        std::clamp(static_cast<int>(std::floor((v - v0_) / strip_height_)), 0, strips - 1);
    bool inside = false;
    // On the boundary counts as inside: Newton projection clamped to the
    // surface's domain stops on a face's boundary where the loop runs along it.
    const double on_boundary = 1e-12 * std::max(u1_ - u0_, v1_ - v0_);
    for (int i = strip_start_[k]; i < strip_start_[k + 1]; ++i) {
        const Segment& s = segments_[strip_segments_[i]];
        if (segment_distance(s, u, v) <= on_boundary) return true;
        // Half-open in v: a vertex on the ray counts for one of its two segments.
        if ((s.va > v) == (s.vb > v)) continue;
        const double x = s.ua + (v - s.va) * (s.ub - s.ua) / (s.vb - s.va);
        if (x > u) inside = !inside;
    }
    return inside;
}

bool FaceRegion::contains(double u, double v) const {
    const double su[3] = {0, period_u_, -period_u_}, sv[3] = {0, period_v_, -period_v_};
    const int nu = period_u_ > 0 ? 3 : 1, nv = period_v_ > 0 ? 3 : 1;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j)
            if (contains_unshifted(u + su[i], v + sv[j])) return true;
    return false;
}

void FaceRegion::wrap(double& u, double& v) const {
    if (period_u_ > 0 && (u < du_min_ || u > du_max_))
        u -= std::floor((u - du_min_) / period_u_) * period_u_;
    if (period_v_ > 0 && (v < dv_min_ || v > dv_max_))
        v -= std::floor((v - dv_min_) / period_v_) * period_v_;
}

} // namespace seamless
