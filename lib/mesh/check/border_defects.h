// SPDX-License-Identifier: MIT
// Border defects for the watertightness check (docs/check.md, steps 3, 5 and 6):
// border loops; cracks, i.e. border edges running along another border edge or
// through border vertices, of the same shell or another; T-junctions where a
// border vertex lies inside another border edge; and seams, the connected runs
// of crack edges. Candidate pairs come from CGAL's box_intersection_d over the
// border edges' boxes, so the work is bounded by the number of border edges
// and of close pairs, whatever the edges' sizes.
#pragma once

#include <seamless/mesh/check/edge_topology.h>

#include <algorithm>
#include <vector>

namespace seamless {

// Tolerance of a crack or T-junction whose edges have local length L, model
// units: max(absolute, relative * L). L is the longer of two edges running along
// each other, or the edge a vertex lies inside: two chordings of one curve differ
// by the sagitta of the longer chord, which grows with its length.
struct GapTolerance {
    double absolute = 0;
    double relative = 0;
    double at(double local_length) const { return std::max(absolute, relative * local_length); }
};

// A border loop: its number of edges, its length (model units) and a vertex on it.
// `closed` is false for a border chain that could not be walked back to its start
// (at non-manifold vertices).
struct BorderLoop {
    int edges = 0;
    double length = 0;
    Vec3 start;
    bool closed = true;
    std::vector<int> triangles; // the triangle of each of its edges, in order
};

// A border vertex within the tolerance of the interior of a border edge (farther
// than the tolerance from both its ends) of a triangle it is not a vertex of.
struct TJunction {
    int vertex = -1;
    Vec3 position;
    int triangle = -1; // the triangle owning the edge
    int v0 = -1, v1 = -1;
    double distance = 0;
    double tolerance = 0; // the tolerance it was judged with
};

// A border edge running along another border edge (overlapping it over more
// than the tolerance, within the tolerance all along the overlap), or one with a
// T-junction vertex inside it.
struct Crack {
    int triangle = -1, v0 = -1, v1 = -1;       // the border edge
    int other_triangle = -1, w0 = -1, w1 = -1; // an edge it runs along, or one at its T-junction
    Vec3 location;                             // midpoint of the first edge
    double gap = 0;                            // largest distance between the two over the overlap
    int seam = -1;                             // index into BorderDefects::seams
};

// A seam: crack edges connected through shared vertices or running along each
// other, usually both sides of one place where two borders should be one edge.
struct Seam {
    int edges = 0;     // crack edges on it, both sides
    double length = 0; // half the total length of its crack edges (one side's length)
    double gap = 0;    // widest crack gap on it
    Vec3 location;     // midpoint of the crack edge nearest its middle
    Vec3 from, to;     // two crack-edge vertices farthest apart: its ends
};

struct BorderDefects {
    std::vector<BorderLoop> loops;
    std::vector<TJunction> t_junctions;
    std::vector<Crack> cracks; // one per crack edge, in border edge order
    std::vector<Seam> seams;   // numbered in the order of their first crack edge
    double widest_crack = 0;
    std::vector<BorderJoin> joins; // crack edge pairs that share a vertex (find_shells)
};

// border: the border edges of edge_topology(mesh).
BorderDefects border_defects(const WeldedMesh& mesh, const std::vector<EdgeUse>& border,
                             GapTolerance tolerance);

} // namespace seamless
