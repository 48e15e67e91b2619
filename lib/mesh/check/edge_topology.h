// SPDX-License-Identifier: MIT
// Edge topology for the watertightness check (docs/check.md, steps 2-4 and 9):
// edges as sorted vertex pairs, border edges, non-manifold edges, inconsistent
// orientation; then shells (triangles connected through shared edges), corner
// fans, non-manifold vertices (a shell pinched) and shell contacts.
#pragma once

#include <seamless/mesh/check/weld.h>

#include <optional>
#include <vector>

namespace seamless {

// An edge-triangle incidence; `forward` when the triangle runs lo -> hi.
struct EdgeUse {
    int lo = -1, hi = -1, triangle = -1;
    bool forward = true;
};

// A non-manifold edge: endpoint vertices (after welding) and positions.
struct EdgeDefect {
    int v0 = -1, v1 = -1;
    Vec3 p0, p1;
    int triangles = 0; // triangles on the edge (>= 3)
};

struct VertexDefect {
    int vertex = -1;
    Vec3 position;
};

struct TrianglePair {
    int t0 = -1, t1 = -1;
    Vec3 location; // on both triangles' shared edge or at the first triangle's centroid
};

struct EdgeTopology {
    std::vector<EdgeUse> uses;               // every triangle side, sorted by (lo, hi, triangle)
    std::vector<std::pair<int, int>> groups; // per edge: first use and number of uses
    std::vector<EdgeUse> border;             // edges with one use, in edge order
    std::vector<EdgeDefect> non_manifold_edges;
    std::vector<TrianglePair> inconsistent_orientation;
    std::vector<int> bad_triangles; // on a non-manifold or misoriented edge
};

EdgeTopology edge_topology(const WeldedMesh& mesh);

// Two border edges that lie along each other from a shared vertex (the sides of
// a T-junction or of a crack closing there): they count as one edge for shells
// and fans, so the defect reported is the crack, not a pinch or a contact.
struct BorderJoin {
    int t0 = -1, t1 = -1; // the two edges' triangles
    int vertex = -1;      // the shared vertex
};

// One shell: its counts and, for closed shells, its measures (shell_measures.h).
struct ComponentReport {
    int vertices = 0, triangles = 0, edges = 0, border_edges = 0;
    bool closed = false;
    // Only for closed components (border_edges == 0):
    std::optional<int> euler;     // V - E + F
    std::optional<int> genus;     // (2 - euler) / 2 when manifold and orientable
    std::optional<double> volume; // CGAL, when the component is a valid closed surface
    std::optional<bool> outward;  // CGAL is_outward_oriented
};

struct Shells {
    std::vector<int> triangle_shell;     // #F shell of each triangle, numbered by first triangle
    std::vector<ComponentReport> shells; // counts filled in; measures left empty
    std::vector<char> manifold_bad;      // per shell: a non-manifold or misoriented element
    std::vector<VertexDefect> non_manifold_vertices; // one shell pinched: two fans of it
    std::vector<VertexDefect> shell_contacts;        // different shells touch (not a defect)
};

// Shells: triangles joined across edges used by two or more triangles and
// across `joins`. A vertex counts once in each shell it belongs to.
Shells find_shells(const WeldedMesh& mesh, const EdgeTopology& topology,
                   const std::vector<BorderJoin>& joins);

} // namespace seamless
