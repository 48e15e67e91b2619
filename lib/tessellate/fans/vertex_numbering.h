// SPDX-License-Identifier: MIT
// Step (d1) of a tessellation pass: the rings' vertices numbered as first met
// in subpatch order, each ring then its centre (shared_edges.h places them).
#pragma once

#include <seamless/tessellate/fans/subpatch_ring.h>
#include <seamless/tessellate/seams/edge_graph.h>
#include <seamless/tessellate/seams/shared_edges.h>
#include <seamless/tessellate/subdivision/subdivision.h>

#include <vector>

namespace seamless {

// Fills rings.vertices[].vertex, rings.centre and vr.positions. With Fig. 3's
// straight segments one by one (a vertex on a straight segment places the
// segment's ends first); otherwise in parallel, the same numbers.
// `leaf_start`: where each patch's subpatches start (one more entry: the end).
// Without straight segments, the vertices of subpatches whose rings are a
// previous pass's (`previous`, with positions) take its positions: each is
// the exact point of the same key.
void number_vertices(const std::vector<Subpatch>& subpatches, const std::vector<int>& leaf_start,
                     const EdgeGraph& graph, int threads, VertexRegistry& vr, SubpatchRings& rings,
                     const PreviousRings& previous = {});

} // namespace seamless
