// SPDX-License-Identifier: MIT
// The crack-free edge registry (paper section 6, Fig. 3). Where a subpatch is
// split and its neighbour across an edge is not, the new vertex Q0 on that edge
// is the midpoint of the straight segment Q1 Q2 of the neighbour's edge, not
// the curve point, and later splits reuse it (Q0,new). Generalised: every
// vertex that lies inside a side of some planar subpatch (of any patch, of any
// surface sharing the boundary) is placed on that side's straight segment, at
// its dyadic parameter; all other vertices are exact surface points. Each
// geometric point is one vertex, keyed canonically, so both sides of an edge
// use the same index. This covers patch edges paired by their control
// polygons; edge_graph.h matches the others by geometry.
//
// Patch edges: 0 = v0 (t = 0), 1 = u1 (s = 1), 2 = v1 (t = 1), 3 = u0 (s = 0),
// each parametrised by increasing s or t; corners as BezierPatch::corner.
//
// Implemented by concept: boundary_match.cpp (BoundaryMatch), edge_registry.cpp
// (EdgeRegistry, over edge_lines.h), vertex_registry.cpp (VertexRegistry).
#pragma once

#include <seamless/spline/bezier_patch.h>
#include <seamless/tessellate/subdivision/subdivision.h>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace seamless {

// Shared boundaries of a set of Bezier patches.
struct BoundaryMatch {
    // Per patch edge (4 * patch + edge): its global edge, -1 when collapsed.
    std::vector<int> edge_group;
    // Per patch edge: runs opposite to its global edge's reference.
    std::vector<char> edge_reversed;
    // Per patch edge: all control points within tol of one point (a pole).
    std::vector<char> collapsed;
    // Per global edge: the reference patch edge (4 * patch + edge) and how many
    // patch edges share it.
    std::vector<int> group_ref, group_size;
    // Per patch corner (4 * patch + corner): representative of the corners
    // within tol of it (weld by position, so poles and touching corners are one).
    std::vector<int> corner_root;
    int shared_edges = 0;    // global edges with two or more patch edges
    int collapsed_edges = 0; // patch edges collapsed to a point
};

// Patch edges match when their boundary control polygons (points and weights)
// agree within tol, forwards or backwards; this also finds a closed surface's
// own seams (a periodic torus' u = 0 and u = 1).
BoundaryMatch match_boundaries(const std::vector<BezierPatch>& patches, double tol);

// Patch edge e of b as a Bezier curve: its order and k-th control point in
// increasing parameter; the grid point at coordinate x along it.
int edge_order(const BezierPatch& b, int e);
HPoint edge_control(const BezierPatch& b, int e, int k);
void edge_grid_point(int e, int x, int& s, int& t);

// A side of a planar subpatch lying on a line: [a, b] in the line's coordinate,
// `side` tells the subpatches on either side (or the patches sharing an edge) apart.
struct LineSegment {
    int a = 0, b = 0;
    int side = 0;
};

// Where a subpatch side lies: line, interval in line coordinates, side tag, and
// whether the line's coordinate runs against the patch's parameter.
struct SideOnLine {
    int line = -1; // -1: on a collapsed edge
    int a = 0, b = 0, side = 0;
    bool reversed = false;
};

// Every line of the subdivision: the global boundary edges and the
// patch-interior split lines (patch, u or v, grid coordinate), with the
// subpatch sides on them. Flat arrays: a patch's interior lines are
// consecutive, numbered as first met in its subpatches; interior_keys
// ascending, interior_lines[i] the line with key interior_keys[i].
struct EdgeRegistry {
    int boundary_lines = 0;                   // line g < boundary_lines is global edge g
    std::vector<std::uint64_t> interior_keys; // key: patch, direction, coordinate
    std::vector<int> interior_lines;
    std::vector<int> offsets;          // per line into segments (CSR)
    std::vector<LineSegment> segments; // per line sorted by (side, a)
    std::vector<SideOnLine> sides;     // per subpatch i and side k: sides[4 i + k]
};

// Side k of rect (0 bottom t = t0, 1 right s = s1, 2 top t = t1, 3 left s = s0).
SideOnLine side_on_line(const EdgeRegistry& reg, const BoundaryMatch& m, int patch,
                        const ParamRect& r, int k);

// A previous pass's registry of the same patches and BoundaryMatch, its
// subpatches in patch order: patch p's subpatches, when same[p], are the
// previous pass's from previous_start[p] on, so are its sides and its
// interior lines' segments (they belong to that patch alone).
struct PreviousRegistry {
    const EdgeRegistry* registry = nullptr;
    const std::vector<int>* previous_start = nullptr;
    const std::vector<char>* same = nullptr;
};

// The same registry for any number of worker threads (parallel.h), and
// with or without a previous pass's (then `subpatches` are in patch order).
EdgeRegistry build_edge_registry(const BoundaryMatch& m, const std::vector<Subpatch>& subpatches,
                                 int threads = 1, const PreviousRegistry& previous = {});

// Line coordinates strictly inside (a, b) where subpatches on other sides of
// the line have corners, ascending; appended to `out`.
void points_inside(const EdgeRegistry& reg, const SideOnLine& side, std::vector<int>& out);

// Canonical identity of a grid point: a welded corner, a point of a global
// edge, or a patch-interior point.
struct VertexKey {
    int kind = 0; // 0 corner (id = corner root), 1 edge (id = global edge, a = coordinate),
                  // 2 interior (id = patch, a = s, b = t on the grid)
    int id = 0, a = 0, b = 0;
    friend bool operator==(const VertexKey&, const VertexKey&) = default;
};
struct VertexKeyHash {
    size_t operator()(const VertexKey& k) const {
        std::uint64_t h = static_cast<std::uint64_t>(k.kind) * 0x9E3779B97F4A7C15ull;
        for (int x : {k.id, k.a, k.b})
            h = (h ^ static_cast<std::uint32_t>(x)) * 0xBF58476D1CE4E5B9ull + (h >> 29);
        return static_cast<size_t>(h);
    }
};
VertexKey vertex_key(const BoundaryMatch& m, int patch, int s, int t);

// Keys of different boundary lines that name one point of a seam (edge_graph.h):
// key -> its representative.
using VertexAlias = std::unordered_map<VertexKey, VertexKey, VertexKeyHash>;

// Vertex indices and positions, created on demand. crack_free = false is the
// naive rule (every vertex the exact curve/surface point) kept for comparison.
struct VertexRegistry {
    const std::vector<BezierPatch>* patches = nullptr;
    const BoundaryMatch* match = nullptr;
    const EdgeRegistry* edges = nullptr;
    const VertexAlias* alias = nullptr; // optional: seams matched geometrically
    bool crack_free = true;
    // Crack-free, true: Fig. 3's rule, a vertex inside a subpatch side lies on
    // that side's straight segment. false: every vertex is its exact surface or
    // curve point; the fans on both sides still run over it by index (each
    // subpatch fans over every vertex on its sides), so no crack opens, and no
    // fan corner sits off the surface by a coarser neighbour's sagitta, which
    // phi cannot take back across a patch edge (error_bound.h).
    bool straight_segments = true;

    std::unordered_map<VertexKey, int, VertexKeyHash> index;
    std::vector<Vec3> positions;
    std::vector<char> placed; // position computed (guards the recursion)
};

// The exact surface or curve point of a key: a corner, the reference patch's
// edge point, an interior surface point (no straight segments).
Vec3 exact_position(const std::vector<BezierPatch>& patches, const BoundaryMatch& m, VertexKey key);
// The key every alias of `key` is numbered under (itself when it has none).
VertexKey canonical_key(const VertexRegistry& vr, VertexKey key);

// Index of the vertex at grid point (s, t) of `patch`, placing it on first use.
int vertex_at(VertexRegistry& vr, int patch, int s, int t);
// Index of the vertex with this key (of any patch), placing it on first use.
int vertex_of(VertexRegistry& vr, VertexKey key);

} // namespace seamless
