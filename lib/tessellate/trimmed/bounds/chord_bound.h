// SPDX-License-Identifier: MIT
// A certified bound on how far an edge's polyline lies from its 3D curve:
// over [ta, tb] the chord from Pa to Pb (linear in t) and the curve C are
// within it of each other, both ways. The curve is bounded as the surface
// S(t, s) = C(t), linear in s, by TriangleBound on a triangle of negligible
// height over [ta, tb]: the hull of the curve's Bernstein coefficients over
// each knot span of [ta, tb] against the chord (the one-dimensional case of
// triangle_bound.h).
#pragma once

#include <seamless/spline/bspline_curve.h>
#include <seamless/tessellate/trimmed/bounds/triangle_bound.h>

namespace seamless {

class ChordBound {
  public:
    explicit ChordBound(const BSplineCurve& c);
    ChordBound(const ChordBound&) = delete; // bound_ refers to surface_
    ChordBound& operator=(const ChordBound&) = delete;

    // cutoff: as TriangleBound's.
    double operator()(double ta, double tb, Vec3 Pa, Vec3 Pb, double cutoff = 0) const;

  private:
    BSplineSurface surface_;
    TriangleBound bound_;
};

} // namespace seamless
