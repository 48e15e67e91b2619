// SPDX-License-Identifier: MIT
// What the passes of a tolerance share (tessellation_pass.h), per Bezier patch
// so that patches can be worked on in parallel: the subdivision criteria's
// verdicts, the final fans' bounds and the last pass's split of each patch.
#pragma once

#include <seamless/base/parallel/cache_line.h>
#include <seamless/tessellate/bounds/fan_certification.h>
#include <seamless/tessellate/fans/subpatch_ring.h>
#include <seamless/tessellate/seams/shared_edges.h>
#include <seamless/tessellate/subdivision/patch_tree.h>
#include <seamless/tessellate/subdivision/subdivision.h>

#include <vector>

namespace seamless {

// One patch's split tree and leaves, on a cache line of its own (the workers
// fill the patches' parts side by side, cache_line.h).
struct alignas(kCacheLine) Part {
    PatchTrees trees;
    std::vector<Subpatch> subpatches;
    int root = -1;
};

struct PassMemo {
    std::vector<FanMemo> verdicts;
    std::vector<KnownBounds> bounds;
    // The last pass's split of each patch, and whether the next pass forces a
    // split in it (else the same verdicts give the same tree: kept).
    std::vector<Part> parts;
    std::vector<char> changed;
    // The previous pass's trees and subpatches, emptied: the next pass refills
    // storage already touched instead of faulting in new pages on one thread.
    std::vector<PatchNode> spare_nodes;
    std::vector<Subpatch> spare_subpatches;
    // Where each patch's subpatches started in the previous pass, its edge
    // registry, rings and their vertices' positions: the next pass copies the
    // parts of patches that cannot have changed (shared_edges.h,
    // subpatch_ring.h). Rings only without seam vertices or aliases (the edge
    // graph's numbers and keys could change).
    std::vector<int> leaf_start;
    EdgeRegistry registry;
    bool rings_kept = false;
    SubpatchRings rings;
    std::vector<Vec3> positions; // the rings' vertices (vertex_numbering.h)
    // The shared boundaries, a function of the patches and the seam tolerance
    // alone: matched once, in the first pass (teapot: 1.2 M instructions a
    // pass, on the calling thread).
    BoundaryMatch match;
    double match_tolerance = -1; // the seam tolerance `match` was made with; -1: none yet
    bool keep = false;           // fill them (only a tolerance takes more than one pass)
    PassMemo(size_t patches, bool keep)
        : verdicts(patches), bounds(patches), parts(patches), changed(patches, 1), keep(keep) {}
};

} // namespace seamless
