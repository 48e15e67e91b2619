// SPDX-License-Identifier: MIT
// A B-spline surface's Bezier patches (section 4: knot insertion), each
// extracted when a point in its knot span is first evaluated. A trimmed
// face samples its surface hundreds of thousands of times over the few
// spans its loops cover, and a Bezier patch evaluates without the B-spline
// basis's chain of divisions (docs/results/cad.md, where the time goes).
// Lazy, so not thread-safe: one per thread, as a face's refinement has.
#pragma once

#include <seamless/spline/bezier_patch.h>
#include <seamless/spline/bspline_surface.h>

#include <cstdint>
#include <deque>
#include <unordered_map>

namespace seamless {

class SpanPatches {
  public:
    explicit SpanPatches(const BSplineSurface& s) : s_(&s) {}
    // The surface's point at (u, v), clamped to its domain as
    // evaluate_point(s, u, v) is; equal to it up to rounding.
    Vec3 point(double u, double v);
    // evaluate(s, u, v) up to rounding (point, derivatives in u and v).
    SurfacePoint at(double u, double v);

  private:
    struct Span {
        BezierPatch patch;
        // Above bicubic, the net times binomial(p, i) binomial(q, j), which
        // points evaluate by Horner's rule; else null.
        const BezierPatch* scaled = nullptr;
    };
    const Span& span(int ku, int kv);
    const Span& span_at(double& u, double& v); // clamped, its span's patch
    const BSplineSurface* s_;
    std::unordered_map<std::int64_t, int> index_; // span (ku, kv) -> spans_
    std::deque<Span> spans_;                      // stable addresses
    std::deque<BezierPatch> scaled_;
    int last_ku_ = -1, last_kv_ = -1; // the span evaluated last
    const Span* last_ = nullptr;
};

} // namespace seamless
