// SPDX-License-Identifier: MIT
// A face's surface as the trimmed pipeline evaluates it: a surface closed
// in u or v (its first and last control columns or rows coincide: a
// periodic surface in its NURBS form) is evaluated with parameters outside
// its domain wrapped into it, so that loops crossing the seam (pcurves
// beyond the domain, as CAD files write them) map to the surface instead of
// being clamped to its edge; beyond an open side it is extended by its
// tangent plane there (a plane's patch smaller than its face's loops).
#pragma once

#include <seamless/spline/bspline_surface.h>

namespace seamless {

class FaceSurface {
  public:
    explicit FaceSurface(const BSplineSurface& s);
    SurfacePoint at(Vec3 uv) const;
    const BSplineSurface& surface() const { return *s_; }

  private:
    const BSplineSurface* s_;
    bool closed_u_ = false, closed_v_ = false;
};

} // namespace seamless
