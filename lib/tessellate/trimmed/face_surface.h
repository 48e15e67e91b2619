// SPDX-License-Identifier: MIT
// A face's surface as the trimmed pipeline evaluates it: a surface closed
// in u or v (its first and last control columns or rows coincide: a
// periodic surface in its NURBS form) is evaluated with parameters outside
// its domain wrapped into it, so that loops crossing the seam (pcurves
// beyond the domain, as CAD files write them) map to the surface instead of
// being clamped to its edge; beyond an open side it is extended by its
// tangent plane there (a plane's patch smaller than its face's loops).
// Its creases are the interior knot lines where it is only C0 (a knot of
// multiplicity >= the degree: a piecewise-planar extrusion's corners), across
// which its normal jumps.
#pragma once

#include <seamless/spline/bspline_surface.h>
#include <seamless/spline/span_patches.h>

#include <array>
#include <vector>

namespace seamless {

class FaceSurface {
  public:
    explicit FaceSurface(const BSplineSurface& s);
    SurfacePoint at(Vec3 uv) const;
    // at(uv) up to rounding, from the spans' Bezier patches.
    SurfacePoint at(Vec3 uv, SpanPatches& spans) const;
    Vec3 point(Vec3 uv) const; // at(uv).point, to the bit: cheaper inside the domain
    // point(uv) up to rounding, inside the domain from the spans' Bezier
    // patches (cheaper still where many points fall in few spans).
    Vec3 point(Vec3 uv, SpanPatches& spans) const;
    const BSplineSurface& surface() const { return *s_; }
    bool closed_u() const { return closed_u_; } // periodic in u: wrapped
    bool closed_v() const { return closed_v_; }
    // An affine map of (u,v) (a plane as a parallelogram's bilinear patch,
    // its weights equal): a flat triangle's distance from it is largest at
    // a corner.
    bool affine() const { return affine_; }
    // True when a crease passes through the box of the (u,v) points (a
    // closed direction's creases repeat by its period).
    bool crosses_crease(const std::array<Vec3, 3>& uv) const;
    // True when uv lies on a crease, where the normal is one side's.
    bool on_crease(Vec3 uv) const { return crosses_crease({uv, uv, uv}); }

  private:
    Vec3 wrapped(Vec3 uv) const; // moved by whole periods into a closed direction's domain
    const BSplineSurface* s_;
    bool closed_u_ = false, closed_v_ = false, affine_ = false;
    std::vector<double> creases_u_, creases_v_;
};

// An upper bound of the distance from q to the surface: the nearest of the
// surface points at uv and of a few damped Gauss-Newton steps from it, taken
// while above `enough`. Where the parametrisation is distorted (towards a
// pole or apex it collapses) the (u,v) image of a triangle strays from it
// though the triangle lies on the surface: its flat points are measured
// against the surface instead.
double distance_to_surface(const FaceSurface& s, SpanPatches& spans, Vec3 q, Vec3 uv,
                           double enough);

} // namespace seamless
