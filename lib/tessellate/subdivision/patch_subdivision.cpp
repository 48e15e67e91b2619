// SPDX-License-Identifier: MIT
#include <seamless/base/parallel/block_schedule.h>
#include <seamless/base/parallel/huge_pages.h>
#include <seamless/base/parallel/parallel.h>
#include <seamless/tessellate/pass_progress.h>
#include <seamless/tessellate/subdivision/patch_subdivision.h>

#include <algorithm>
#include <atomic>
#include <cmath>

namespace seamless {

double patch_cost(const BezierPatch& b, double D) {
    double mss = 0, mtt = 0;
    for (int i = 0; i <= b.p; ++i)
        for (int j = 0; j <= b.q; ++j) {
            if (i >= 1 && i < b.p)
                mss = std::max(mss,
                               norm(b.point(i + 1, j) - 2.0 * b.point(i, j) + b.point(i - 1, j)));
            if (j >= 1 && j < b.q)
                mtt = std::max(mtt,
                               norm(b.point(i, j + 1) - 2.0 * b.point(i, j) + b.point(i, j - 1)));
        }
    const double cost =
        (1 + std::sqrt(b.p * (b.p - 1) * mss / D)) * (1 + std::sqrt(b.q * (b.q - 1) * mtt / D));
    return std::isfinite(cost) ? cost : 0.0;
}

PatchSubdivision::PatchSubdivision(const std::vector<BezierPatch>& patches,
                                   const SubdivisionOptions& options, double D, int threads,
                                   std::int64_t max_leaves, bool keep)
    : patches_(patches), options_(options), D_(D), threads_(threads), max_leaves_(max_leaves),
      keep_(keep), verdicts_(patches.size()), parts_(patches.size()) {}

void PatchSubdivision::take_spare(std::vector<PatchNode>&& nodes,
                                  std::vector<Subpatch>&& subpatches) {
    spare_nodes_ = std::move(nodes);
    spare_subpatches_ = std::move(subpatches);
}

bool PatchSubdivision::split_parts(const std::vector<char>& changed,
                                   const SubdivisionOptions& options,
                                   const PassProgress* progress) {
    const int np = static_cast<int>(patches_.size());
    std::int64_t kept = 0;
    for (int i = 0; i < np; ++i)
        if (!changed[i]) kept += static_cast<std::int64_t>(parts_[i].subpatches.size());
    std::atomic<std::int64_t> leaves_left{max_leaves_ - kept};
    // Patches differ in cost by ten times and more (teapot): dearest first.
    std::vector<double> cost(np);
    std::vector<int> order(np);
    for (int i = 0; i < np; ++i) cost[i] = patch_cost(patches_[i], D_), order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return cost[a] > cost[b]; });
    // Progress by the patches' costs done of the cost of those split again.
    double total = 0;
    for (int i = 0; i < np; ++i)
        if (changed[i]) total += cost[i];
    std::atomic<double> done{0};
    pull_blocks(np, 1, threads_, &order, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            if (!changed[i]) continue;
            SubdivisionOptions o = options;
            o.memo = keep_ ? &verdicts_[i] : nullptr;
            o.leaves_left = &leaves_left;
            // Emptied, not freed: a later pass refills the storage this one touched.
            Part& part = parts_[i];
            part.trees.nodes.clear();
            part.trees.roots.clear();
            part.trees.depth = 0;
            part.subpatches.clear();
            part.root = seamless::subdivide(patches_[i], i, o, part.trees, part.subpatches);
            if (progress && *progress)
                progress->within(0, PassProgress::kSubdivided, done.fetch_add(cost[i]) + cost[i],
                                 total);
        }
    });
    return leaves_left.load() >= 0;
}

void PatchSubdivision::concatenate(const PatchRanges& at, PatchTrees* trees,
                                   std::vector<Subpatch>& subpatches) {
    const int np = static_cast<int>(patches_.size());
    // The previous pass's storage, with room for a pass that splits more: its
    // pages are touched already.
    if (trees) {
        trees->nodes.swap(spare_nodes_);
        trees->nodes.clear();
    }
    subpatches.swap(spare_subpatches_);
    subpatches.clear();
    auto room = [&](auto& v, size_t n) {
        if (n > v.capacity()) reserve_huge(v, keep_ ? n + n / 8 : n, threads_);
    };
    if (trees) {
        room(trees->nodes, at.node_start[np]);
        trees->nodes.resize(at.node_start[np]);
        trees->roots.resize(np);
    }
    room(subpatches, at.leaf_start[np]);
    subpatches.resize(at.leaf_start[np]);
    parallel_chunks(np, threads_, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const Part& p = parts_[i];
            const int node0 = at.node_start[i], leaf0 = at.leaf_start[i];
            for (size_t j = 0; trees && j < p.trees.nodes.size(); ++j) {
                PatchNode n = p.trees.nodes[j];
                for (int& c : n.child)
                    if (c >= 0) c += node0;
                if (n.subpatch >= 0) n.subpatch += leaf0;
                trees->nodes[node0 + j] = n;
            }
            for (size_t j = 0; j < p.subpatches.size(); ++j) {
                Subpatch sp = p.subpatches[j];
                sp.node += node0;
                subpatches[leaf0 + j] = sp;
            }
            if (trees) trees->roots[i] = p.root + node0;
        }
    });
}

PatchRanges PatchSubdivision::subdivide(const std::vector<char>& changed,
                                        const std::unordered_set<std::uint64_t>& split,
                                        PatchTrees* trees, std::vector<Subpatch>& subpatches,
                                        const PassProgress* progress) {
    SubdivisionOptions o = options_;
    o.split = &split;
    o.nodes = trees != nullptr;
    if (!split_parts(changed, o, progress)) return PatchRanges{{}, {}, true};
    const int np = static_cast<int>(patches_.size());
    PatchRanges at{std::vector<int>(np + 1, 0), std::vector<int>(np + 1, 0)};
    for (int i = 0; i < np; ++i) {
        at.node_start[i + 1] = at.node_start[i] + static_cast<int>(parts_[i].trees.nodes.size());
        at.leaf_start[i + 1] = at.leaf_start[i] + static_cast<int>(parts_[i].subpatches.size());
        if (trees) trees->depth = std::max(trees->depth, parts_[i].trees.depth);
    }
    concatenate(at, trees, subpatches);
    if (!keep_) std::vector<Part>().swap(parts_); // one pass: no copy kept
    return at;
}

} // namespace seamless
