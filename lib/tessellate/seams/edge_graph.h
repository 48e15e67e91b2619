// SPDX-License-Identifier: MIT
// The edge graph of a model: boundary curves shared geometrically (paper
// section 6, Fig. 3, extended to seams whose two sides share no control
// polygon). match_boundaries pairs whole patch edges whose control polygons
// agree; here every other patch edge meets the others by geometry: it may
// coincide with a whole edge of another patch, a part of one, or a chain of
// edges of other patches (other surfaces or its own surface's seam), in either
// direction, whatever the degrees, knots, weights and parametrisations on
// either side, within the seam tolerance. On each shared piece of curve the
// vertices of both sides (the subpatch corners on it) become one chain: a
// vertex of one side within the tolerance of a vertex of the other is one
// vertex (an alias), every other one is inserted into the other side's
// subpatch sides at its projected parameter. Both sides' fans then run over
// the same vertices, by index, so the seam has no crack and no T-junction.
//
// Every seam vertex is an exact curve point of its own side (these lines have
// one side only, so Fig. 3's straight-segment rule never moves them); the
// other side's fan sees it at its projected parameter and its actual
// position, which keeps the error bound (error_bound.h) valid.
#pragma once

#include <seamless/tessellate/seams/shared_edges.h>

#include <span>
#include <vector>

namespace seamless {

// A vertex of another boundary line lying inside this one: its parameter on
// the line's reference patch edge (the line coordinate / kParamOne, a double)
// and its key (a representative: vertex_of needs no alias for it).
struct SeamPoint {
    double x = 0;
    VertexKey key;
};

struct EdgeGraph {
    // Per boundary line (global edge of BoundaryMatch): the other lines'
    // vertices strictly inside it, sorted by x (CSR over offsets).
    std::vector<int> offsets;
    std::vector<SeamPoint> points;
    // Keys of different lines naming one point: key -> representative.
    VertexAlias alias;
    int seams = 0;         // pairs of boundary lines sharing a piece of curve
    int seam_vertices = 0; // vertices inserted into other lines plus keys aliased
};

// Matches every boundary line that match_boundaries left unpaired against the
// others: a subpatch corner P on line h belongs to line g when its distance to
// g's curve is at most tol (projection by Gauss-Newton from the nearest of a
// few samples, after a bounding-box test) and the two curves agree next to P
// (the midpoints between P and its neighbouring vertices, on g or on h, lie
// within tol of the other curve): isolated crossings and touching ends are
// no seams.
EdgeGraph build_edge_graph(const std::vector<BezierPatch>& patches, const BoundaryMatch& m,
                           const EdgeRegistry& reg, double tol);

// The other lines' points inside boundary line `line`, by increasing x.
inline std::span<const SeamPoint> seam_points(const EdgeGraph& g, int line) {
    if (line < 0 || line + 1 >= static_cast<int>(g.offsets.size())) return {};
    return {g.points.data() + g.offsets[line],
            static_cast<size_t>(g.offsets[line + 1] - g.offsets[line])};
}

} // namespace seamless
