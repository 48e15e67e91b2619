// SPDX-License-Identifier: MIT
// A pass's inputs for the tests of its steps: the teapot tessellated at
// D = 0.01, its boundaries, edge registry and edge graph, and where each
// patch's subpatches start.
#pragma once

#include "test_util.h"

#include <seamless/model/model.h>
#include <seamless/tessellate/seams/edge_graph.h>
#include <seamless/tessellate/seams/shared_edges.h>
#include <seamless/tessellate/tessellation.h>

#include <vector>

namespace seamless::test {

struct TeapotPass {
    Model model = load_model(model_path("teapot.json"));
    std::vector<BezierPatch> patches = bezier_patches(model);
    Tessellation t = tessellate(model, patches, options());
    BoundaryMatch match = match_boundaries(patches, t.stats.seam_tolerance);
    EdgeRegistry reg = build_edge_registry(match, t.subpatches, 2);
    EdgeGraph graph = build_edge_graph(patches, match, reg, t.stats.seam_tolerance);
    std::vector<int> leaf_start = leaf_starts();

    static TessellationOptions options() {
        TessellationOptions o;
        o.tolerance = 0.01;
        return o;
    }
    std::vector<int> leaf_starts() const {
        const int np = static_cast<int>(patches.size());
        std::vector<int> at(np + 1, 0);
        for (const Subpatch& sp : t.subpatches) ++at[sp.patch + 1];
        for (int p = 0; p < np; ++p) at[p + 1] += at[p];
        return at;
    }
};

} // namespace seamless::test
