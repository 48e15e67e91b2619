// SPDX-License-Identifier: MIT
// How a face's (u, v) moved when its surface took its exact NURBS form.
// The rational forms of circles parametrise them by tan(angle / 2) per arc,
// not by the angle the file's cylinders, cones, spheres, tori and surfaces
// of revolution use, so a pcurve written against the file's surface must be
// carried over to the B-spline surface's parameters: (u, v) -> (phi(u),
// chi(v)), one monotone map per direction (the conversions are tensor
// products of curve conversions). The surface stays exact; the pcurves
// that cross the moved directions are refitted within a tolerance.
// Internal to the STEP/IGES module (libseamless_step_iges.so).
#pragma once

#include <seamless/spline/bspline_curve.h>
#include <seamless/spline/bspline_surface.h>

#include <Geom_Surface.hxx>

#include <vector>

namespace seamless::step_iges {

class ParameterMap {
  public:
    // `file_surface` over [u1, u2] x [v1, v2] became `converted` (its whole
    // domain, corners to corners).
    ParameterMap(const Handle(Geom_Surface) & file_surface, const BSplineSurface& converted,
                 double u1, double u2, double v1, double v2);

    bool identity() const { return identity_u_ && identity_v_; }
    // False when Newton's method did not find where the surfaces meet along
    // the lines u() and v() use (the pcurves cannot be carried over).
    bool valid() const { return valid_; }
    // The converted surface's parameters of the file's (u, v).
    double u(double file_u) const;
    double v(double file_v) const;

    // The pcurve `pc` (against the file's surface) over [t0, t1], carried
    // over: exact where it is an iso-line of the moved directions, else
    // interpolated (cubic, the same parameter t) between its kinks within
    // `uv_tol`. `error` gets the largest distance found at check points, in
    // (u, v). Empty when the interpolation fails.
    BSplineCurve carry(const BSplineCurve& pc, double t0, double t1, double uv_tol,
                       double& error) const;

  private:
    // The converted surface's (u, v) where it meets the file's surface at
    // (fu, fv), by Newton's method from the corners' linear map.
    // Returns the distance left between the two points.
    double invert(double fu, double fv, double& cu, double& cv) const;
    // The file's parameters of the converted surface's interior knots.
    std::vector<double> knot_images(int axis) const;
    std::vector<double> breaks(const BSplineCurve& pc, double t0, double t1) const;

    Handle(Geom_Surface) file_;
    BSplineSurface conv_; // a copy: the model's list may grow
    double u1_, u2_, v1_, v2_;
    bool identity_u_ = true, identity_v_ = true, valid_ = true;
    std::vector<double> images_u_, images_v_; // knot_images, where not identity
};

} // namespace seamless::step_iges
