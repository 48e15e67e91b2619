// SPDX-License-Identifier: MIT
// Watertightness verification of a triangle mesh: welding of
// bit-identical positions (weld.h); edge topology: borders, non-manifold
// elements, orientation, shells and where they touch (edge_topology.h); border
// defects: seam cracks, T-junctions, border loops (border_defects.h); degenerate,
// duplicated and intersecting triangles (self_intersections.h); and per closed
// shell Euler characteristic, genus, volume and outward orientation
// (shell_measures.h). A mesh with solid ids (or part ids) is judged solid by
// solid: where solids touch is the model's geometry, reported as contacts, not
// a defect of the mesh. docs/check.md explains every item.
#pragma once

#include <seamless/base/triangle_mesh.h>
#include <seamless/mesh/check/border_defects.h>
#include <seamless/mesh/check/edge_topology.h>
#include <seamless/mesh/check/self_intersections.h>

#include <vector>

namespace seamless {

// What a check judges apart: the mesh's solids (TriangleMesh::triangle_solid),
// else its parts (triangle_part), else the whole mesh as one.
enum class CheckBodies { whole, parts, solids };

struct CheckOptions {
    // gap: absolute tolerance of cracks and T-junctions, model units; <= 0 means
    // the default rule: max(gap_floor * d_max, relative_gap * L), where L is the
    // local edge length (border_defects.h, GapTolerance) and d_max the largest
    // extent of the mesh's bounding box. relative_gap 1% catches the cracks a
    // tessellation leaves between surfaces while an opening as wide as a few
    // percent of its edges stays a border.
    double gap = 0;
    double relative_gap = 0.01;
    double gap_floor = 1e-6;
    // weld: first merge vertices whose positions are bit-identical; false judges
    // the mesh's own indices.
    bool weld = true;
    // require_closed: every component (shell) must be closed for check_passed().
    bool require_closed = false;
    // by_solid: judge each solid (else part) of a mesh with such ids apart;
    // false judges the whole mesh as one union, touching solids included.
    bool by_solid = true;
};

// Two bodies that touch or overlap: the triangle pairs between them.
struct BodyContact {
    int body0 = -1, body1 = -1; // ids (solid or part), body0 < body1
    int triangle_pairs = 0;
    Vec3 location; // of the first pair
};

struct CheckReport {
    double d_max = 0;
    GapTolerance gap; // the tolerance rule actually used (relative = 0 with an absolute gap)
    bool welded = true;
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
    std::vector<Crack> cracks; // one per crack edge
    std::vector<Seam> seams;   // crack edges grouped into connected runs
    double widest_crack = 0;
    std::vector<TriangleDefect> degenerate_triangles;
    std::vector<TrianglePair> duplicated_triangles; // t1 repeats t0's vertex set
    std::vector<TrianglePair> inconsistent_orientation;
    std::vector<TrianglePair> self_intersections; // within one shell
    std::vector<TrianglePair> overlaps;           // between shells (not a defect)

    // Bodies judged apart: what they are, how many (-1, no solid or part,
    // counts as one), vertices copied because bodies shared them (weld.h),
    // intersecting triangle pairs of different bodies (not a defect), and
    // those pairs counted per pair of bodies, ordered by the pair.
    CheckBodies bodies = CheckBodies::whole;
    int body_count = 1;
    int body_vertex_copies = 0;
    std::vector<TrianglePair> contacts;
    std::vector<BodyContact> body_contacts;

    // One component, a shell: triangles connected through shared edges (manifold
    // or not, or border edges lying along each other from a shared vertex: the
    // sides of a T-junction or crack). Shells touching only at vertices stay
    // apart; such a vertex counts in each.
    std::vector<ComponentReport> components;
    std::vector<int> triangle_component; // #F shell index of each triangle
    std::vector<int> component_body;     // per component, its body's id (-1 judged whole)
};

CheckReport check_mesh(const TriangleMesh& mesh, const CheckOptions& options = {});

// Number of defects: crack edges, T-junctions, non-manifold edges and vertices,
// degenerate and duplicated triangles, inconsistent orientation pairs and
// self-intersections (shell contacts, overlaps between shells and contacts
// between bodies do not count).
int defect_count(const CheckReport& report);

// No defects and, when options.require_closed, every component closed.
bool check_passed(const CheckReport& report, const CheckOptions& options);

} // namespace seamless
