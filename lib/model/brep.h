// SPDX-License-Identifier: MIT
// The boundary representation of a CAD model: trimmed faces bounded by loops
// of edges, the edges' 3D curves and the faces' pcurves, vertices, shells and
// solids (ISO 10303-42's topology, as STEP and IGES 186/514 carry it). Each
// face lies on one surface of Model::surfaces; the loops say which part of
// its (u,v) domain the face is. The trimmed pipeline (tessellate/trimmed/)
// discretises every edge once and shares it by index between the faces that
// use it, which is what keeps the mesh of a closed solid closed.
//
// Conventions the readers establish and validate_brep checks:
// - A coedge's pcurve is parametrised like its edge's 3D curve over the
//   edge's [t0, t1] (STEP's and OpenCASCADE's "same parameter"): pcurve(t)
//   on the face's surface is within the edge's tolerance of curve(t).
// - A loop's coedges form a closed chain in (u,v) and in 3D.
// - A seam edge of a periodic face appears twice in that face's loops, with
//   two pcurves (one on each side of the seam) and opposite `reversed`.
// - A degenerate edge (a pole or apex: the 3D curve is one point) has no 3D
//   curve, one vertex at both ends, and a pcurve along the pole's side.
#pragma once

#include <seamless/base/vec.h>
#include <seamless/spline/bspline_curve.h>

#include <string>
#include <vector>

namespace seamless {

struct BRepVertex {
    Vec3 point;
    double tolerance = 0; // model units: the file's points within this are this vertex
};

struct BRepEdge {
    int curve = -1;           // index into BRep::curves; -1: degenerate (pole or apex)
    double t0 = 0, t1 = 0;    // parameter range, t0 < t1, of the curve and of every pcurve
    int start = -1, end = -1; // vertices at t0 and t1 (equal for a closed or degenerate edge)
    double tolerance = 0;     // model units: the pcurves' images are within this of the curve
    bool degenerate() const { return curve < 0; }
};

// An edge as a face's loop uses it.
struct BRepCoedge {
    int edge = -1;
    bool reversed = false; // the loop runs from the edge's end to its start
    int pcurve = -1;       // index into BRep::pcurves: the edge in the face's (u,v) domain
};

// A closed chain of coedges, in order.
struct BRepLoop {
    std::vector<BRepCoedge> coedges;
};

struct BRepFace {
    int surface = -1;            // index into Model::surfaces
    bool reversed = false;       // the outward side is -(dP/du x dP/dv)
    std::vector<BRepLoop> loops; // loops[0] is the outer loop, the others holes
    std::string name;            // the file's entity ("#55", "DE9") or name; unique
};

struct BRepShell {
    std::vector<int> faces;
    bool closed = false; // every edge used twice (a seam counts as two uses by its face)
};

struct BRepSolid {
    std::vector<int> shells; // shells[0] the outer one
    std::string name;
};

struct BRep {
    std::vector<BRepVertex> vertices;
    std::vector<BSplineCurve> curves;  // 3D curves of the edges
    std::vector<BSplineCurve> pcurves; // (u, v, 0) curves of the coedges
    std::vector<BRepEdge> edges;
    std::vector<BRepFace> faces;
    std::vector<BRepShell> shells; // shells of solids and free shells
    std::vector<BRepSolid> solids;

    bool empty() const { return faces.empty(); }
};

} // namespace seamless
