// SPDX-License-Identifier: MIT
// Planarity test of a (sub)patch (paper section 6, after Lane et al. 1980): by the
// convex hull property the patch is planar within eps1 when every control point
// is within eps1 of the plane through three corners, and its boundary curves are
// straight within eps2 when their inner control points are within eps2 of the
// chord. Rational patches use their projected control points (positive weights).
#pragma once

#include <seamless/spline/bezier_patch.h>

namespace seamless {

// The two measures the test compares with eps1 and eps2, in model units.
struct Planarity {
    // Largest distance of a control point to the plane of a non-degenerate corner
    // triple (every such triple is tried). Without one (collapsed or collinear
    // corners) the distance to the corners' line or common point instead.
    double plane = 0;
    // Largest distance of an inner control point of a boundary curve to the
    // segment joining the curve's end points (a collapsed curve: to its point).
    double boundary = 0;

    // Section 6: "planar iff ... less than a tolerance".
    bool planar(double eps1, double eps2) const { return plane < eps1 && boundary < eps2; }
};

Planarity planarity(const BezierPatch& b);
inline bool is_planar(const BezierPatch& b, double eps1, double eps2) {
    return planarity(b).planar(eps1, eps2);
}

// Largest distance of control points to the chords of the curves in u (rows of
// fixed j) or in v (columns of fixed i): how far from straight the patch is in
// that direction; the subdivision splits the less flat direction.
double flatness_u(const BezierPatch& b);
double flatness_v(const BezierPatch& b);

} // namespace seamless
