// SPDX-License-Identifier: MIT
// Step (a) of a tessellation pass (paper section 6): every Bezier patch split
// on its own (subdivision.h), in parallel, dearest first; the trees then laid
// end to end in patch order (prefix sums, copied in parallel): the same arrays
// for any thread count.
#pragma once

#include <seamless/spline/bezier_patch.h>
#include <seamless/tessellate/pass_memo.h>
#include <seamless/tessellate/subdivision/patch_tree.h>
#include <seamless/tessellate/subdivision/subdivision.h>

#include <vector>

namespace seamless {

class PassProgress;

// Expected relative cost of subdividing `b` to deviation D, for the order of
// the work only: a subpatch of size h deviates about h^2 |second difference|,
// so about sqrt(M/D) splits per direction.
double patch_cost(const BezierPatch& b, double D);

// Where each patch's nodes and leaves start in the concatenated arrays (one
// more entry: the ends).
struct PatchRanges {
    std::vector<int> node_start, leaf_start;
    // The pass would need more than max_leaves subpatches: the subdivision
    // stopped early, nothing was concatenated (both ranges empty).
    bool over_budget = false;
};

// Splits the patches that memo.changed marks (the others keep memo.parts),
// with memo.verdicts when memo.keep, and concatenates every patch's tree and
// leaves into `trees` (unless null: no trees wanted, TessellationOptions::
// patch_trees) and `subpatches`. D: the deviation patch_cost orders by. At
// most max_leaves subpatches in all (the kept patches' included), else
// over_budget.
PatchRanges subdivide_patches(const std::vector<BezierPatch>& patches,
                              const SubdivisionOptions& sub, double D, int threads, PassMemo& memo,
                              PatchTrees* trees, std::vector<Subpatch>& subpatches,
                              std::int64_t max_leaves, const PassProgress* progress = nullptr);

} // namespace seamless
