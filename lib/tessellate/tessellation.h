// SPDX-License-Identifier: MIT
// Crack-free adaptive tessellation of a model (paper section 6): every Bezier
// patch is split by the planarity test, or until a requested deviation is
// certified (subdivision.h, error_bound.h), shared boundaries are matched
// across patches and surfaces (shared_edges.h, edge_graph.h), vertices follow the
// straight-midpoint rule of Fig. 3 (with a requested tolerance: exact surface
// points, VertexRegistry::straight_segments), each planar subpatch becomes a fan from
// its centre over every vertex on its sides, and the binary patch trees of
// Proposition 11, remark 2 are built in the same pass.
#pragma once

#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation_options.h>
#include <seamless/tessellate/tessellation_result.h>

#include <vector>

namespace seamless {

Tessellation tessellate(const Model& model, const TessellationOptions& options = {});

// Same, from Bezier patches already extracted (bezier_patches(model)); the
// patch indices of the result refer to `patches`.
Tessellation tessellate(const Model& model, const std::vector<BezierPatch>& patches,
                        const TessellationOptions& options);

} // namespace seamless
