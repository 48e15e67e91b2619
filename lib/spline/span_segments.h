// SPDX-License-Identifier: MIT
// A B-spline curve's Bezier segments, each computed when a point in its
// knot span is first evaluated (the curve analogue of span_patches.h). A
// B-rep edge's curve is sampled hundreds of times while its polyline is
// split, often at degree 6 to 9 (intersection curves as CAD systems
// approximate them), where the B-spline basis costs p(p+1)/2 divisions a
// point and a Bezier segment's Bernstein sums none.
// Lazy, so not thread-safe: one per thread, as an edge's discretisation has.
#pragma once

#include <seamless/spline/bspline_curve.h>

#include <array>
#include <deque>
#include <unordered_map>

namespace seamless {

class SpanSegments {
  public:
    explicit SpanSegments(const BSplineCurve& c) : c_(&c) {}
    // The curve's point at t, clamped to its domain as evaluate_point(c, t)
    // is; equal to it up to rounding.
    Vec3 point(double t);
    // dC/dt at t (clamped likewise): evaluate(c, t).tangent up to rounding,
    // from the segment's hodograph where the B-spline basis would need its
    // derivatives too.
    Vec3 tangent(double t);

  private:
    struct Segment {
        double t0 = 0, t1 = 1;
        std::array<HPoint, kMaxDegree + 1> cp;     // homogeneous Bezier points
        std::array<HPoint, kMaxDegree + 1> scaled; // cp[i] times binomial(p, i)
    };
    const Segment& segment(int k);
    const Segment& segment_at(double& t); // t clamped, its span's segment
    const BSplineCurve* c_;
    std::unordered_map<int, int> index_; // span k -> segments_
    std::deque<Segment> segments_;       // stable addresses
    int last_k_ = -1;                    // the span evaluated last, and its segment
    const Segment* last_ = nullptr;
};

} // namespace seamless
