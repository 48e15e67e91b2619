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

  private:
    const BezierPatch& patch(int ku, int kv);
    const BSplineSurface* s_;
    std::unordered_map<std::int64_t, int> index_; // span (ku, kv) -> patches_
    std::deque<BezierPatch> patches_;             // stable addresses
    int last_ku_ = -1, last_kv_ = -1;             // the span evaluated last, and its patch
    const BezierPatch* last_ = nullptr;
};

} // namespace seamless
