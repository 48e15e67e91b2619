// SPDX-License-Identifier: MIT
#include <seamless/base/segment_distance.h>
#include <seamless/spline/span_segments.h>
#include <seamless/tessellate/trimmed/edge_discretisation.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

namespace seamless {

namespace {

// |dP/du x dP/dv| below this fraction of |dP/du|^2 + |dP/dv|^2 is a pole's:
// one derivative (nearly) vanishes. Files write a pole's control points to
// their own precision (trj3_s1-al: 1e-10 apart), and a derivative that
// small has a direction of rounding, a quarter turn off the true normal.
constexpr double kSingular = 1e-8;

} // namespace

Vec3 unit_normal(const FaceSurface& s, Vec3 uv, Vec3 inward, SpanPatches* spans) {
    for (double step : {0.0, 1e-6, 1e-4, 1e-2}) {
        const Vec3 q = uv + step * (inward - uv);
        const SurfacePoint sp = spans ? s.at(q, *spans) : s.at(q);
        const Vec3 n = sp.normal();
        if (norm(n) > kSingular * (dot(sp.du, sp.du) + dot(sp.dv, sp.dv))) return normalize(n);
    }
    return {};
}

double angle_between(Vec3 a, Vec3 b) {
    if (!(norm(a) > 0) || !(norm(b) > 0)) return 0;
    return std::atan2(norm(cross(a, b)), dot(a, b));
}

AngleLimit::AngleLimit(double angle)
    : angle_(angle),
      cos2_(angle < 0.5 * std::numbers::pi ? std::cos(angle) * std::cos(angle) : -1) {}

bool AngleLimit::exceeded(Vec3 a, Vec3 b) const {
    // Within the angle by a margin far above the cosine's rounding: a
    // non-negative cosine whose square is above cos^2 of the limit.
    constexpr double kMargin = 1 + 1e-6;
    const double d = dot(a, b);
    if (d > 0 && d * d > kMargin * cos2_ * dot(a, a) * dot(b, b)) return false;
    return angle_between(a, b) > angle_;
}

namespace {

constexpr int kMaxDepth = 24;
// Tangents at a segment's ends are taken this fraction inside it.
constexpr double kInside = 1e-9;

// A segment end's data that both segments meeting there use: its 3D point,
// and per face its (u,v) point and surface normal (computed when first
// asked: across a crease it is not). Fixed arrays: no allocation per
// segment; an edge used by more faces computes the rest each time.
constexpr int kCachedUses = 4;
struct SegmentEnd {
    double t = 0;
    Vec3 point;
    std::array<Vec3, kCachedUses> uv, normal;
    std::array<bool, kCachedUses> has_normal{};
    std::array<double, kCachedUses> offset{-1, -1, -1, -1}; // -1: not computed
};

struct Splitter {
    const BRep& brep;
    const BRepEdge& e;
    const std::vector<EdgeOnFace>& uses;
    const EdgeCriteria& c;
    EdgePolyline& line;
    SpanSegments* samples = nullptr; // the curve's, for the chord samples (not degenerate)
    const AngleLimit limit = AngleLimit(c.angle);

    Vec3 point(double t) const {
        if (t == e.t0) return brep.vertices[e.start].point;
        if (t == e.t1) return brep.vertices[e.end].point;
        return e.degenerate() ? brep.vertices[e.start].point
                              : evaluate_point(brep.curves[e.curve], t);
    }

    SegmentEnd end_at(double t) const {
        SegmentEnd x;
        x.t = t;
        x.point = point(t);
        for (size_t k = 0; k < uses.size() && k < kCachedUses; ++k)
            x.uv[k] = evaluate_point(*uses[k].pcurve, t);
        return x;
    }
    Vec3 uv(const SegmentEnd& x, size_t k) const {
        return k < kCachedUses ? x.uv[k] : evaluate_point(*uses[k].pcurve, x.t);
    }
    Vec3 normal(SegmentEnd& x, size_t k) const {
        const EdgeOnFace& use = uses[k];
        if (k >= kCachedUses) return unit_normal(use.surface, uv(x, k), use.inward);
        if (!x.has_normal[k]) x.normal[k] = unit_normal(use.surface, x.uv[k], use.inward);
        x.has_normal[k] = true;
        return x.normal[k];
    }

    // How far the end's point lies off use k's surface at its (u,v) point
    // (FaceDomain::offset): asked only of chords above the aim.
    double offset(SegmentEnd& x, size_t k) const {
        const EdgeOnFace& use = uses[k];
        if (k >= kCachedUses) return distance(x.point, use.surface.point(uv(x, k)));
        if (x.offset[k] < 0) x.offset[k] = distance(x.point, use.surface.point(x.uv[k]));
        return x.offset[k];
    }

    // The largest sampled distance of [a, b]'s curve and (u,v) images from
    // its chord, or infinity when a tangent or normal turns too far; m is
    // the middle's end data.
    double deviation(SegmentEnd& a, SegmentEnd& b, SegmentEnd& m) const {
        const Vec3 pa = a.point, pb = b.point;
        double d = 0;
        if (!e.degenerate()) {
            const BSplineCurve& curve = brep.curves[e.curve];
            constexpr int kSamples = 16;
            for (int k = 1; k < kSamples; ++k)
                d = std::max(d, point_segment_distance(
                                    samples->point(a.t + (b.t - a.t) * k / kSamples), pa, pb));
            // A span shorter than the samples' spacing could hide a wiggle.
            for (auto knot = std::upper_bound(curve.knots.begin(), curve.knots.end(), a.t);
                 knot != curve.knots.end() && *knot < b.t; ++knot)
                d = std::max(d, point_segment_distance(samples->point(*knot), pa, pb));
            // The ends' tangents from inside [a, b]: at a kink (a break of
            // discretise_edge) the curve's other side turns away.
            const double in = kInside * (b.t - a.t);
            const Vec3 ta = samples->tangent(a.t + in), tb = samples->tangent(b.t - in),
                       tm = samples->tangent(0.5 * (a.t + b.t));
            if (limit.exceeded(ta, tm) || limit.exceeded(tm, tb) || limit.exceeded(ta, tb))
                return INFINITY;
        }
        for (size_t k = 0; k < uses.size(); ++k) {
            const EdgeOnFace& use = uses[k];
            const Vec3 ua = uv(a, k), ub = uv(b, k);
            for (double s : {0.25, 0.5, 0.75}) {
                const Vec3 q = lerp(ua, ub, s);
                double dq = point_segment_distance(use.surface.point(q), pa, pb);
                // The ends' offsets off the surface are the chord's, not its sag's.
                if (dq > kDeviationAim * c.deviation)
                    dq -= offset_allowance(std::lerp(offset(a, k), offset(b, k), s), c.deviation);
                d = std::max(d, dq);
            }
            // The midpoint too: a closed edge's ends have one normal. Across
            // a crease the normal jumps however short the segment.
            const Vec3 um = uv(m, k);
            if (use.surface.crosses_crease({ua, um, ub})) continue;
            const Vec3 na = normal(a, k), nb = normal(b, k), nm = normal(m, k);
            if (limit.exceeded(na, nm) || limit.exceeded(nm, nb) || limit.exceeded(na, nb))
                return INFINITY;
        }
        return std::max(d, 0.0);
    }

    // Appends the points after a up to b.
    void split(SegmentEnd& a, SegmentEnd& b, int depth) {
        SegmentEnd m = end_at(0.5 * (a.t + b.t));
        const double d = deviation(a, b, m);
        const bool room = depth < kMaxDepth && static_cast<int>(line.t.size()) < c.max_points &&
                          m.t > a.t && m.t < b.t;
        // Samples miss the largest deviation by a few per cent: aim below D.
        if (d > kDeviationAim * c.deviation && room) {
            split(a, m, depth + 1);
            split(m, b, depth + 1);
            return;
        }
        if (d > kDeviationAim * c.deviation) line.limited = true;
        if (std::isfinite(d)) line.deviation = std::max(line.deviation, d);
        line.t.push_back(b.t);
        line.points.push_back(b.point);
    }
};

// Rounding, relative to a point's coordinates: closer points are one.
constexpr double kSamePoint = 1e-12;

bool same_point(Vec3 a, Vec3 b) {
    return distance(a, b) <= kSamePoint * (1 + std::max(norm(a), norm(b)));
}

// Points where the curve stands still between two breaks (a composite
// curve's zero-length piece: its kinks at both ends are breaks), when every
// pcurve stands still there too: left in, they would be a zero-length
// segment of every face's loop. The edge's ends stay.
void drop_stationary_points(EdgePolyline& line, const std::vector<EdgeOnFace>& uses) {
    const auto stationary = [&](size_t i, size_t j) {
        if (!same_point(line.points[i], line.points[j])) return false;
        for (const EdgeOnFace& use : uses)
            if (!same_point(evaluate_point(*use.pcurve, line.t[i]),
                            evaluate_point(*use.pcurve, line.t[j])))
                return false;
        return true;
    };
    size_t n = 1;
    for (size_t k = 1; k < line.t.size(); ++k) {
        const bool last = k + 1 == line.t.size();
        if (stationary(n - 1, k)) {
            if (!last) continue;
            if (n > 1) --n; // the end vertex replaces the interior point
        }
        line.t[n] = line.t[k];
        line.points[n] = line.points[k];
        ++n;
    }
    line.t.resize(n);
    line.points.resize(n);
}

} // namespace

EdgePolyline discretise_edge(const BRep& brep, int edge, const std::vector<EdgeOnFace>& uses,
                             const EdgeCriteria& criteria) {
    const BRepEdge& e = brep.edges[edge];
    EdgePolyline line;
    std::optional<SpanSegments> samples;
    if (!e.degenerate()) samples.emplace(brep.curves[e.curve]);
    Splitter s{brep, e, uses, criteria, line, samples ? &*samples : nullptr};
    line.t.push_back(e.t0);
    line.points.push_back(s.point(e.t0));
    // A closed edge needs three segments to bound anything; a curve only C0
    // at a knot (a polyline's corner) turns there however short the chords,
    // so its kinks are points of the polyline from the start.
    std::vector<double> breaks;
    const int pieces = !e.degenerate() && e.start == e.end ? 4 : 1;
    for (int k = 1; k < pieces; ++k) breaks.push_back(e.t0 + (e.t1 - e.t0) * k / pieces);
    if (!e.degenerate()) {
        const BSplineCurve& curve = brep.curves[e.curve];
        for (int i = curve.degree + 1; i < curve.size();) {
            int j = i;
            while (j < curve.size() && curve.knots[j] == curve.knots[i]) ++j;
            if (j - i >= curve.degree && curve.knots[i] > e.t0 && curve.knots[i] < e.t1)
                breaks.push_back(curve.knots[i]);
            i = j;
        }
    }
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    breaks.push_back(e.t1);
    SegmentEnd a = s.end_at(e.t0);
    for (double t : breaks) {
        if (!(t > a.t)) continue;
        SegmentEnd b = s.end_at(t);
        s.split(a, b, 0);
        a = b;
    }
    drop_stationary_points(line, uses);
    return line;
}

void halve_segments(const BRep& brep, int edge, EdgePolyline& line,
                    const std::vector<int>& segments) {
    const BRepEdge& e = brep.edges[edge];
    const std::vector<EdgeOnFace> none;
    const EdgeCriteria criteria;
    Splitter s{brep, e, none, criteria, line};
    std::vector<double> t{line.t.front()};
    std::vector<Vec3> points{line.points.front()};
    auto next = segments.begin();
    for (size_t k = 1; k < line.t.size(); ++k) {
        const bool listed = next != segments.end() && *next == static_cast<int>(k - 1);
        if (listed) ++next;
        const double m = 0.5 * (line.t[k - 1] + line.t[k]);
        const Vec3 pm = s.point(m);
        // A midpoint on a piece where the curve stands still would make a
        // zero-length segment (a degenerate edge is all one point: its
        // points differ in (u,v)).
        const bool still = !e.degenerate() &&
                           (same_point(pm, line.points[k - 1]) || same_point(pm, line.points[k]));
        if ((segments.empty() || listed) && m > line.t[k - 1] && m < line.t[k] && !still) {
            t.push_back(m);
            points.push_back(pm);
        }
        t.push_back(line.t[k]);
        points.push_back(line.points[k]);
    }
    line.t = std::move(t);
    line.points = std::move(points);
}

} // namespace seamless
