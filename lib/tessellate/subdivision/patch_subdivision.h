// SPDX-License-Identifier: MIT
// Step (a) of a tessellation pass (paper section 6): every Bezier patch split
// on its own (subdivision.h), in parallel, dearest first; the trees then laid
// end to end in patch order (prefix sums, copied in parallel): the same arrays
// for any thread count.
#pragma once

#include <seamless/base/parallel/cache_line.h>
#include <seamless/spline/bezier_patch.h>
#include <seamless/tessellate/subdivision/patch_tree.h>
#include <seamless/tessellate/subdivision/subdivision.h>

#include <cstdint>
#include <unordered_set>
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

// One patch's split tree and leaves, on a cache line of its own (the workers
// fill the patches' parts side by side, cache_line.h).
struct alignas(kCacheLine) Part {
    PatchTrees trees;
    std::vector<Subpatch> subpatches;
    int root = -1;
};

// The patches' split trees over the passes of a tolerance: each patch's tree
// and leaves (kept for the next pass, which splits only the patches it
// changed), the criteria's verdicts, and the previous pass's concatenated
// arrays, emptied: the next pass refills storage already touched instead of
// faulting in new pages on one thread.
class PatchSubdivision {
  public:
    // `options` without split, memo and leaves_left (set per pass). D: the
    // deviation patch_cost orders by. At most max_leaves subpatches in a pass.
    // `keep`: later passes follow (the verdicts and parts are kept).
    PatchSubdivision(const std::vector<BezierPatch>& patches, const SubdivisionOptions& options,
                     double D, int threads, std::int64_t max_leaves, bool keep);

    // Splits the patches that `changed` marks (the others keep their parts),
    // forcing the splits in `split` (subpatch_key), and concatenates every
    // patch's tree and leaves into `trees` (unless null: no trees wanted,
    // TessellationOptions::patch_trees) and `subpatches`. At most max_leaves
    // subpatches in all (the kept patches' included), else over_budget.
    PatchRanges subdivide(const std::vector<char>& changed,
                          const std::unordered_set<std::uint64_t>& split, PatchTrees* trees,
                          std::vector<Subpatch>& subpatches,
                          const PassProgress* progress = nullptr);

    // A pass's concatenated arrays, for the next pass to refill.
    void take_spare(std::vector<PatchNode>&& nodes, std::vector<Subpatch>&& subpatches);

    // Patches whose parts are kept: all, or none after a pass without `keep`.
    int kept_patches() const { return static_cast<int>(parts_.size()); }
    // Frees patch p < kept_patches()'s tree, leaves and verdicts (no pass follows).
    void release(int p) {
        verdicts_[p] = FanMemo();
        parts_[p] = Part();
    }

  private:
    // Splits the changed patches into their parts, dearest first; false when
    // the budget ran out.
    bool split_parts(const std::vector<char>& changed, const SubdivisionOptions& options,
                     const PassProgress* progress);
    // The parts laid end to end at `at`.
    void concatenate(const PatchRanges& at, PatchTrees* trees, std::vector<Subpatch>& subpatches);

    const std::vector<BezierPatch>& patches_;
    SubdivisionOptions options_;
    double D_;
    int threads_;
    std::int64_t max_leaves_;
    bool keep_;
    std::vector<FanMemo> verdicts_;
    std::vector<Part> parts_;
    std::vector<PatchNode> spare_nodes_;
    std::vector<Subpatch> spare_subpatches_;
};

} // namespace seamless
