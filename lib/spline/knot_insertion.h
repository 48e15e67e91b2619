// SPDX-License-Identifier: MIT
// Knot insertion (Boehm's algorithm) and Bezier extraction (paper section 4: "by
// inserting new knots into the knot vectors U and V, any B-spline surface may be
// partitioned into a net of Bezier surfaces").
#pragma once

#include <seamless/spline/bezier_patch.h>
#include <seamless/spline/bspline_surface.h>

#include <vector>

namespace seamless {

// Control net in homogeneous coordinates, rows along u: (i, j) at i * cols + j.
struct HomogeneousNet {
    int degree_u = 3, degree_v = 3;
    int rows = 0, cols = 0; // nu, nv
    std::vector<double> knots_u, knots_v;
    std::vector<HPoint> cp;

    HPoint& at(int i, int j) { return cp[static_cast<size_t>(i) * cols + j]; }
    const HPoint& at(int i, int j) const { return cp[static_cast<size_t>(i) * cols + j]; }
};

HomogeneousNet homogeneous_net(const BSplineSurface& s);

// Boehm: inserts the knot t (inside the domain) once into the u (or v) knot
// vector; the surface is unchanged, the net grows by one row (or column).
void insert_knot_u(HomogeneousNet& net, double t);
void insert_knot_v(HomogeneousNet& net, double t);

// Bezier extraction: every distinct knot of the domain is raised to multiplicity
// degree, after which each non-empty knot span rectangle is one Bezier patch,
// in order of increasing u, then v. Each patch remembers `surface_index` and
// its parameter rectangle.
std::vector<BezierPatch> bezier_patches(const BSplineSurface& s, int surface_index);

// Number of Bezier patches of s: non-empty spans in u times in v.
int bezier_patch_count(const BSplineSurface& s);

} // namespace seamless
