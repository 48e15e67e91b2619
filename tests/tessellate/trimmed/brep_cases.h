// SPDX-License-Identifier: MIT
// Hard cases of trimmed B-rep faces (issue 28, section 2), built as exact
// NURBS: plates with holes (free and touching the outer loop), a box of six
// trimmed planes, a cylinder, a cone with an apex, a sphere with two poles,
// a torus, a sliver face, an edge shorter than the deviation, and scaled
// copies. Each comes with what its mesh must be and the exact distance to
// its surfaces, computed independently of the NURBS (analytic forms).
#pragma once

#include <seamless/model/model.h>

#include <functional>
#include <string>
#include <vector>

namespace seamless::test {

struct BRepCase {
    std::string name;
    Model model;
    bool closed = false; // a solid: closed, one shell
    int euler = 0;       // V - E + F of the mesh
    // Distance of a point to the (untrimmed) surface `surface`, model units.
    std::function<double(int surface, Vec3 p)> distance;
};

BRepCase plate_with_holes(int holes);      // 0 .. 4 free circular holes
BRepCase plate_beyond_its_plane();         // the plane's patch is smaller than the loops
BRepCase plate_with_touching_holes();      // two holes touching the outer loop, one free
BRepCase box_solid(double short_edge = 0); // > 0: one edge split off this short
BRepCase cylinder_solid(double scale = 1);
BRepCase cylinder_across_seam(); // a cylindrical patch whose pcurves cross u = 4 (the seam)
BRepCase cone_solid();
BRepCase sphere_solid();
BRepCase torus_solid();
BRepCase freeform_face(); // a bicubic graph z = f(x, y) trimmed to [0.2, 0.8]^2 by iso-curves
BRepCase sliver_face(double height); // a lens between a line and a flat arc of this height
BRepCase crossing_loops();           // a hole crossing the outer loop: cannot be triangulated
BRepCase tangent_hole(); // a disk whose hole touches its rim tangentially, at the rim's vertex
BRepCase bent_plate();   // one degree-1 surface folded by 90 degrees at a C0 knot (a crease)

// Every case above with its default arguments and the scaled cylinders.
std::vector<BRepCase> all_brep_cases();

} // namespace seamless::test
