// SPDX-License-Identifier: MIT
// Small B-rep models for the B-rep tests, built as a reader would: a planar
// square plate with a square hole (a degree-1 surface and lines), and a
// surface of revolution around z whose face is bounded by two circles and a
// seam edge used twice with its two pcurves; a top radius of 0 makes it a
// cone whose apex is a degenerate edge. And an assembly of the two.
#pragma once

#include <seamless/model/model.h>

#include <cmath>

namespace seamless::test {

// A degree-1 curve from a to b over [0, 1]; (u, v, 0) points make a pcurve.
inline BSplineCurve line(Vec3 a, Vec3 b) {
    BSplineCurve c;
    c.degree = 1;
    c.knots = {0, 0, 1, 1};
    c.points = {a, b};
    return c;
}

inline void add_edge(BRep& b, BSplineCurve curve, BSplineCurve pcurve, int start, int end) {
    b.edges.push_back({static_cast<int>(b.curves.size()), 0, 1, start, end, 1e-7});
    b.curves.push_back(std::move(curve));
    b.pcurves.push_back(std::move(pcurve));
}

// The plate [0, 10]^2 in z = 0 over (u, v) in [0, 1]^2 (S = (10u, 10v, 0)),
// with the hole [3, 7]^2. Each coedge uses the pcurve of the same index.
inline Model plate_with_hole() {
    Model m;
    BSplineSurface s;
    s.name = "plate";
    s.degree_u = s.degree_v = 1;
    s.size_u = s.size_v = 2;
    s.knots_u = s.knots_v = {0, 0, 1, 1};
    s.points = {{0, 0, 0}, {0, 10, 0}, {10, 0, 0}, {10, 10, 0}};
    m.surfaces.push_back(s);
    BRep& b = m.brep;
    const double corners[2][4][2] = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}},
                                     {{0.3, 0.3}, {0.7, 0.3}, {0.7, 0.7}, {0.3, 0.7}}};
    BRepFace face;
    face.surface = 0;
    face.name = "plate";
    for (int l = 0; l < 2; ++l) {
        const int first = static_cast<int>(b.vertices.size());
        for (int k = 0; k < 4; ++k)
            b.vertices.push_back({{10 * corners[l][k][0], 10 * corners[l][k][1], 0}, 1e-7});
        for (int k = 0; k < 4; ++k) {
            const int i = first + k, j = first + (k + 1) % 4;
            const Vec3 a{corners[l][k][0], corners[l][k][1], 0};
            const Vec3 z{corners[l][(k + 1) % 4][0], corners[l][(k + 1) % 4][1], 0};
            add_edge(b, line(b.vertices[i].point, b.vertices[j].point), line(a, z), i, j);
        }
        // The hole runs clockwise: its edges (counter-clockwise) reversed.
        BRepLoop loop;
        for (int k = 0; k < 4; ++k) {
            const int e = first + (l == 0 ? k : 3 - k);
            loop.coedges.push_back({e, l == 1, e});
        }
        face.loops.push_back(loop);
    }
    b.faces.push_back(face);
    b.shells.push_back({{0}, false});
    return m;
}

// A quarter-circle NURBS (degree 2, 9 points, 4 arcs) of radius r at height z.
inline void circle(double r, double z, std::vector<Vec3>& points, std::vector<double>& weights) {
    const double c[9][2] = {{1, 0},   {1, 1},  {0, 1},  {-1, 1}, {-1, 0},
                            {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    for (int k = 0; k < 9; ++k) {
        points.push_back({r * c[k][0], r * c[k][1], z});
        weights.push_back(k % 2 ? std::sqrt(0.5) : 1.0);
    }
}

// The side of a cylinder (top_radius 1) or cone (0) of height 2 around z:
// S(u, v) = the circle of radius 1 + v (top_radius - 1) at height 2v, at
// parameter u. Edges: 0 the bottom circle, 1 the top circle (degenerate when
// top_radius is 0), 2 the seam at u = 0 = 1. Pcurves: 0 bottom, 1 top, 2 the
// seam at u = 0, 3 at u = 1.
inline Model revolved(double top_radius) {
    Model m;
    BSplineSurface s;
    s.name = "side";
    s.degree_u = 2;
    s.degree_v = 1;
    s.size_u = 9;
    s.size_v = 2;
    s.knots_u = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    s.knots_v = {0, 0, 1, 1};
    std::vector<Vec3> bottom, top;
    std::vector<double> w, unused;
    circle(1, 0, bottom, w);
    circle(top_radius, 2, top, unused);
    for (int i = 0; i < 9; ++i) {
        s.points.insert(s.points.end(), {bottom[i], top[i]});
        s.weights.insert(s.weights.end(), {w[i], w[i]});
    }
    m.surfaces.push_back(s);
    BRep& b = m.brep;
    b.vertices = {{{1, 0, 0}, 1e-7}, {{top_radius, 0, 2}, 1e-7}};
    for (const auto* pts : {&bottom, &top}) {
        BSplineCurve c;
        c.degree = 2;
        c.knots = s.knots_u;
        c.points = *pts;
        c.weights = w;
        b.curves.push_back(c);
    }
    b.curves.push_back(line({1, 0, 0}, {top_radius, 0, 2}));
    b.pcurves = {line({0, 0, 0}, {1, 0, 0}), line({0, 1, 0}, {1, 1, 0}), line({0, 0, 0}, {0, 1, 0}),
                 line({1, 0, 0}, {1, 1, 0})};
    b.edges = {{0, 0, 1, 0, 0, 1e-7}, {1, 0, 1, 1, 1, 1e-7}, {2, 0, 1, 0, 1, 1e-7}};
    if (top_radius == 0) b.edges[1].curve = -1;
    BRepFace face;
    face.surface = 0;
    face.name = top_radius == 0 ? "cone" : "cylinder";
    // Counter-clockwise in (u, v): bottom, the seam up at u = 1, the top
    // backwards, the seam down at u = 0.
    face.loops.push_back({{{0, false, 0}, {2, false, 3}, {1, true, 1}, {2, true, 2}}});
    b.faces.push_back(face);
    b.shells.push_back({{0}, false});
    return m;
}

inline AffineMap translation(double x, double y, double z) {
    AffineMap m;
    m.m[3] = x;
    m.m[7] = y;
    m.m[11] = z;
    return m;
}

// x -> -x: a mirroring placement.
inline AffineMap mirror_x() {
    AffineMap m;
    m.m[0] = -1;
    return m;
}

// Two parts, "plate" (the plate with a hole, red) and "tube" (a cylinder,
// its face green), placed four times: the plate once at the root, the tube
// twice beside it (once mirrored) and once in a sub-assembly moved up; the
// plate on layer "plates", the tube's face on the hidden layer "tube face".
inline Model small_assembly() {
    Model m = test::plate_with_hole();
    const Model tube = test::revolved(1);
    append_brep(m.brep, tube.brep, static_cast<int>(m.surfaces.size()), AffineMap{});
    m.surfaces.insert(m.surfaces.end(), tube.surfaces.begin(), tube.surfaces.end());
    Assembly& a = m.assembly;
    a.colours = {{1, 0, 0, 1}, {0, 1, 0, 0.5}};
    a.parts = {{"plate", 1, 1, 0, 0}, {"tube", 1, 1, 0, -1}};
    a.face_colours = {-1, 1};
    a.nodes = {{"top", -1, AffineMap{}, -1},
               {"plate-1", 0, AffineMap{}, 0},
               {"tube-1", 0, translation(20, 0, 0), 1},
               {"tube-2", 0, mirror_x(), 1},
               {"sub", 0, translation(0, 0, 5), -1},
               {"tube-3", 4, translation(0, 30, 0), 1}};
    // A whole part on one layer, the tube's face on a hidden one.
    a.layers = {{"plates", true, {0}, {}, {}}, {"tube face", false, {}, {}, {1}}};
    return m;
}

} // namespace seamless::test
