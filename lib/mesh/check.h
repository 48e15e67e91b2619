// SPDX-License-Identifier: MIT
// Watertightness verification of a triangle mesh (issue 4): welding of
// bit-identical positions, topology (borders, non-manifold elements,
// orientation, shells and where they touch), geometric defects (T-junctions,
// cracks, degenerate and duplicated triangles, self-intersections) and per closed
// shell Euler characteristic, genus, volume and outward orientation.
// docs/check.md explains every item.
#pragma once

#include <seamless/tessellate/triangle_mesh.h>

#include <optional>
#include <string>
#include <vector>

namespace seamless {

struct CheckOptions {
    // gap: tolerance of T-junctions and cracks, model units; <= 0 means the
    // default 1e-6 * d_max (d_max: largest extent of the mesh's bounding box).
    double gap = 0;
    // weld: first merge vertices whose positions are bit-identical; false judges
    // the mesh's own indices.
    bool weld = true;
    // require_closed: every component (shell) must be closed for check_passed().
    bool require_closed = false;
};

// A border loop: its number of edges, its length (model units) and a vertex on it.
// `closed` is false for a border chain that could not be walked back to its start
// (at non-manifold vertices).
struct BorderLoop {
    int edges = 0;
    double length = 0;
    Vec3 start;
    bool closed = true;
};

// An edge defect: endpoint vertices (after welding) and positions.
struct EdgeDefect {
    int v0 = -1, v1 = -1;
    Vec3 p0, p1;
    int triangles = 0; // triangles on the edge (non-manifold: >= 3)
};

struct VertexDefect {
    int vertex = -1;
    Vec3 position;
};

// A vertex within the gap of the interior of a border edge it does not belong to.
struct TJunction {
    int vertex = -1;
    Vec3 position;
    int triangle = -1; // the triangle owning the edge
    int v0 = -1, v1 = -1;
    double distance = 0;
};

// A border edge running along another border edge, within the gap, with no shared vertex.
struct Crack {
    int triangle = -1, v0 = -1, v1 = -1;       // the border edge
    int other_triangle = -1, w0 = -1, w1 = -1; // the edge it runs along
    Vec3 location;                             // midpoint of the first edge
    double gap = 0;                            // largest endpoint distance
};

struct TrianglePair {
    int t0 = -1, t1 = -1;
    Vec3 location; // on both triangles' shared edge or at the first triangle's centroid
};

struct TriangleDefect {
    int triangle = -1;
    Vec3 location; // centroid
};

// One component, a shell: triangles connected through shared edges (manifold or
// not, or border edges lying along each other from a shared vertex: the sides of
// a T-junction or crack). Shells touching only at vertices stay apart; such a
// vertex counts in each.
struct ComponentReport {
    int vertices = 0, triangles = 0, edges = 0, border_edges = 0;
    bool closed = false;
    // Only for closed components (border_edges == 0):
    std::optional<int> euler;     // V - E + F
    std::optional<int> genus;     // (2 - euler) / 2 when manifold and orientable
    std::optional<double> volume; // CGAL, when the component is a valid closed surface
    std::optional<bool> outward;  // CGAL is_outward_oriented
};

struct CheckReport {
    double d_max = 0, gap = 0; // gap actually used
    bool welded = true;        // whether welding was applied
    int input_vertices = 0;
    int welded_vertices = 0; // vertices merged into an earlier one with identical position
    int unreferenced_vertices = 0;
    int vertices = 0, triangles = 0, edges = 0;

    int border_edges = 0;
    std::vector<BorderLoop> border_loops;
    bool closed = false; // no border edges

    std::vector<EdgeDefect> non_manifold_edges;
    std::vector<VertexDefect> non_manifold_vertices; // one shell pinched: two fans of it
    std::vector<VertexDefect> shell_contacts;        // different shells touch (not a defect)
    std::vector<TJunction> t_junctions;
    std::vector<Crack> cracks;
    double widest_crack = 0;
    std::vector<TriangleDefect> degenerate_triangles;
    std::vector<TrianglePair> duplicated_triangles; // t1 repeats t0's vertex set
    std::vector<TrianglePair> inconsistent_orientation;
    std::vector<TrianglePair> self_intersections; // within one shell
    std::vector<TrianglePair> overlaps;           // between shells (not a defect)

    std::vector<ComponentReport> components;
    std::vector<int> triangle_component; // #F shell index of each triangle
};

CheckReport check_mesh(const TriangleMesh& mesh, const CheckOptions& options = {});

// Number of defects: cracks, T-junctions, non-manifold edges and vertices,
// degenerate and duplicated triangles, inconsistent orientation pairs and
// self-intersections (shell contacts and overlaps between shells do not count).
int defect_count(const CheckReport& report);

// No defects and, when options.require_closed, every component closed.
bool check_passed(const CheckReport& report, const CheckOptions& options);

// The whole report as JSON; defect lists are cut at `max_listed` entries each
// (their full counts are always given).
std::string to_json(const CheckReport& report, int max_listed = 1000);

} // namespace seamless
