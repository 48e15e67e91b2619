// SPDX-License-Identifier: MIT
// One pass of the tessellation (paper section 6): (a) split trees, (b, c)
// shared boundaries and the subpatch sides on every line, (d0) rings, (d1)
// vertex numbering, (d2) certified bounds, (d3, d4) normals and fans. With a
// tolerance, tessellation.cpp repeats it, splitting the subpatches whose final
// fan bound is above it; the passes share a PassMemo.
#pragma once

#include <seamless/model/model.h>
#include <seamless/tessellate/pass_memo.h>
#include <seamless/tessellate/tessellation_options.h>
#include <seamless/tessellate/tessellation_result.h>

#include <cstdint>
#include <unordered_set>
#include <vector>

namespace seamless {

// `split`: subpatches to split whatever the criteria say (subpatch_key).
// Without `last`, a pass that leaves subpatches above the tolerance returns
// before building the mesh (another pass follows). The patch trees' hulls
// come out multiplied by `hull_scale` (write_fans), the rest at the model's scale.
// `pass` (0 first) places its part of TessellationOptions::progress.
Tessellation tessellate_pass(const Model& model, const std::vector<BezierPatch>& patches,
                             const TessellationOptions& options,
                             const std::unordered_set<std::uint64_t>& split, PassMemo& memo,
                             bool last, double hull_scale = 1, int pass = 0);

// Whether the pass after this one splits `sp` (its final fan's bound is above
// the tolerance, when there is one).
inline bool splits_again(const Subpatch& sp, double tolerance, int max_depth) {
    return tolerance > 0 && sp.error_bound > tolerance && sp.depth < max_depth;
}

// Refuses a tessellation past TessellationOptions::max_triangles: throws
// TriangleBudgetError (tessellation.h).
[[noreturn]] void refuse_triangle_budget(const Model& model, const TessellationOptions& options);

} // namespace seamless
