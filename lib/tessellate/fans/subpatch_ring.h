// SPDX-License-Identifier: MIT
// The ring of a planar subpatch (paper section 6, Fig. 3): its boundary,
// counterclockwise in (s, t) from corner (s0, t0), with the four corners and,
// crack-free, every vertex a finer neighbour put on a side and every seam
// vertex of another patch lying on it (edge_graph.h). Its fan runs from the
// subpatch's centre over this ring.
#pragma once

#include <seamless/spline/bezier_patch.h>
#include <seamless/tessellate/seams/edge_graph.h>
#include <seamless/tessellate/seams/shared_edges.h>
#include <seamless/tessellate/subdivision/subdivision.h>

#include <vector>

namespace seamless {

// A ring vertex of a subpatch: its parameters on the subpatch's patch (on the
// grid, or -1 for the coordinate along the side of a seam vertex of another
// patch, whose parameter is a projection) and its mesh vertex.
struct RingVertex {
    int s = 0, t = 0;
    double fs = 0, ft = 0;
    int foreign = -1; // index into EdgeGraph::points
    int vertex = -1;
};

// A vertex inside a side, by its line coordinate / kParamOne: a grid point or
// another line's seam vertex.
struct SideVertex {
    double x = 0;
    int grid = 0, foreign = -1;
};

// Subpatches' rings over one edge registry and edge graph, with scratch
// storage reused from ring to ring (one collector per worker).
class RingCollector {
  public:
    // crack_free false: the four corners alone.
    RingCollector(const EdgeRegistry& reg, const EdgeGraph& graph, bool crack_free)
        : reg_(reg), graph_(graph), crack_free_(crack_free) {}
    // The ring of subpatch `i` (rect `r`; its sides reg.sides[4 i + k]) into `ring`.
    void collect(int i, const ParamRect& r, std::vector<RingVertex>& ring);

  private:
    const EdgeRegistry& reg_;
    const EdgeGraph& graph_;
    bool crack_free_;
    std::vector<int> scratch_;
    std::vector<SideVertex> inside_;
};

// Every subpatch's ring, laid end to end in subpatch order, and its centre.
struct SubpatchRings {
    std::vector<RingVertex> vertices;
    std::vector<int> start;         // per subpatch into vertices; one more entry: the end
    std::vector<Vec3> centre_point; // S at the centre of the subpatch's parameters
    std::vector<int> centre;        // its mesh vertex (vertex_numbering.h)
    // Per slot of `vertices`: its vertex's canonical key, where the numbering
    // ran in parallel (vertex_numbering.h; else empty). A later pass copies
    // the keys of rings it copies.
    std::vector<VertexKey> keys;
};

// A previous pass's rings, copied where they cannot have changed: patch p's
// subpatches, when same[p], are the previous pass's from previous_start[p]
// on (leaf_start: where they start now), and so are their sides' lines.
// With `positions` (the previous pass's vertices, rings.vertices[].vertex
// their indices) the numbering takes their positions from there too.
struct PreviousRings {
    const SubpatchRings* rings = nullptr;
    const std::vector<int>* previous_start = nullptr;
    const std::vector<int>* leaf_start = nullptr;
    const std::vector<char>* same = nullptr;
    const std::vector<Vec3>* positions = nullptr;
};

// In parallel, the same arrays for any thread count; vertex and centre are
// left to the numbering.
SubpatchRings collect_rings(const std::vector<BezierPatch>& patches,
                            const std::vector<Subpatch>& subpatches, const EdgeRegistry& reg,
                            const EdgeGraph& graph, bool crack_free, int threads,
                            const PreviousRings& previous = {});

} // namespace seamless
