// SPDX-License-Identifier: MIT
// Exact NURBS pieces and a small builder for hand-made B-reps (brep_cases.h):
// lines, rational quadratic circles and arcs, planes, cylinders, cones,
// spheres and tori whose u direction is the same circle as the 3D edge
// curves, so pcurves are exact (straight lines in (u,v), or the plane's
// affine image of the 3D curve).
#pragma once

#include <seamless/model/model.h>

#include <string>
#include <vector>

namespace seamless::test {

// A straight segment a -> b over [0, 1].
BSplineCurve nurbs_line(Vec3 a, Vec3 b);
// The full circle c + r (cos s a + sin s b), s = 0 .. 2 pi, as 4 rational
// quadratic quarter arcs over [0, 4]: starts at c + r a.
BSplineCurve nurbs_circle(Vec3 c, double r, Vec3 a, Vec3 b);
// The half circle from c - r b to c + r b through c + r a, over [0, 2].
BSplineCurve nurbs_half_circle(Vec3 c, double r, Vec3 a, Vec3 b);
// A rational quadratic arc (one Bezier span over [0, 1]).
BSplineCurve nurbs_conic(Vec3 a, Vec3 m, Vec3 b, double w);

// The plane o + u ex + v ey over [u0, u1] x [v0, v1] (bilinear, exact).
struct PlaneFrame {
    Vec3 o, ex, ey; // ex, ey orthonormal
    Vec3 uv(Vec3 p) const { return {dot(p - o, ex), dot(p - o, ey), 0}; }
    BSplineSurface surface(double u0, double u1, double v0, double v1) const;
    // A curve lying in the plane, as the plane's pcurve (affine image).
    BSplineCurve pcurve(const BSplineCurve& c) const;
};

// Surfaces of revolution about the z axis through `base`, u the circle of
// nurbs_circle (over [0, 4]) and v along the profile.
BSplineSurface cylinder_surface(Vec3 base, double r, double h);   // v in [0, 1]
BSplineSurface cone_surface(Vec3 base, double r, double h);       // v in [0, 1] to the apex
BSplineSurface sphere_surface(Vec3 c, double r);                  // v in [0, 2] pole to pole
BSplineSurface torus_surface(Vec3 c, double major, double minor); // v in [0, 4]

struct BRepBuilder {
    Model m;
    std::vector<BRepLoop> loops; // of the face being built

    int vertex(Vec3 p);
    int surface(BSplineSurface s, const std::string& name);
    int edge(const BSplineCurve& c, int start, int end, double tolerance = 1e-9);
    int degenerate_edge(int vertex, double t0, double t1);
    // Adds a coedge with its pcurve to loops.back() (new_loop() first).
    void use(int edge, bool reversed, const BSplineCurve& pcurve);
    void new_loop() { loops.push_back({}); }
    int face(int surface, bool reversed, const std::string& name);
    // One shell of all faces (closed or not) and, when closed, a solid.
    Model finish(bool closed, const std::string& name);
};

} // namespace seamless::test
