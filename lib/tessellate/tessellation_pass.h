// SPDX-License-Identifier: MIT
// The passes of a tessellation (paper section 6), each in the paper's order:
// (a) split trees, (b, c) shared boundaries and the subpatch sides on every
// line, (d0) rings, (d1) vertex numbering, (d2) certified bounds, (d3, d4)
// normals and fans, then the surfaces' orientation. With a tolerance,
// tessellation.cpp repeats the pass, splitting the subpatches whose final fan
// bound is above it; what the passes share (the split trees, the criteria's
// verdicts, the known bounds, the previous pass's arrays) lives in the
// TessellationPass, so that a later pass redoes only what changed and refills
// storage the earlier one touched.
#pragma once

#include <seamless/base/phase_clock.h>
#include <seamless/model/model.h>
#include <seamless/tessellate/bounds/fan_certification.h>
#include <seamless/tessellate/fans/subpatch_ring.h>
#include <seamless/tessellate/pass_progress.h>
#include <seamless/tessellate/seams/edge_graph.h>
#include <seamless/tessellate/seams/shared_edges.h>
#include <seamless/tessellate/subdivision/patch_subdivision.h>
#include <seamless/tessellate/tessellation_options.h>
#include <seamless/tessellate/tessellation_result.h>

#include <chrono>
#include <cstdint>
#include <unordered_set>
#include <vector>

namespace seamless {

// Step (b, c)'s product: the subpatch sides on every line (the edge
// registry) and the boundaries matched by geometry (the edge graph).
struct Boundaries {
    EdgeRegistry registry;
    EdgeGraph graph;
};

// Step (d0)'s product: every subpatch's ring; `previous`: the previous pass's
// rings were copied for the patches `same` marks.
struct Rings {
    SubpatchRings rings;
    std::vector<char> same;
    bool previous = false;
};

class TessellationPass {
  public:
    // The model, patches and options outlive the passes. The patch trees'
    // hulls come out multiplied by `hull_scale` (write_fans), the rest at the
    // model's scale.
    TessellationPass(const Model& model, const std::vector<BezierPatch>& patches,
                     const TessellationOptions& options, double hull_scale = 1);

    // Pass `pass` (0 first; places its part of TessellationOptions::progress).
    // Without `last`, a pass that leaves subpatches above the tolerance
    // returns before building the mesh (another pass follows).
    Tessellation run(int pass, bool last);

    // After a pass that another follows: its subpatches above the tolerance
    // are split in the next, and its arrays refilled (`t` is emptied).
    void split_again(Tessellation& t);

  private:
    // Each step reads the products of the steps before it and adds its own to
    // out_, the pass's Tessellation.
    PatchRanges subdivide();
    Boundaries find_boundaries();
    Rings collect_rings(const PatchRanges& ranges, const Boundaries& boundaries);
    VertexRegistry number_vertices(const PatchRanges& ranges, const Boundaries& boundaries,
                                   Rings& rings);
    void certify(const PatchRanges& ranges, const Boundaries& boundaries, const Rings& rings,
                 const VertexRegistry& vertices, bool last);
    void keep_for_next_pass(const PatchRanges& ranges, Boundaries& boundaries, Rings& rings,
                            VertexRegistry& vertices);
    void release_before_mesh(Boundaries& boundaries, Rings& rings);
    void build_mesh(const PatchRanges& ranges, const Rings& rings, VertexRegistry& vertices);

    // The previous pass's rings where `rings` copied them, else none.
    PreviousRings previous_rings(const PatchRanges& ranges, const Rings& rings) const;
    // Ends a phase: its seconds and the pass's progress.
    void lap(double& seconds, double fraction);

    const Model& model_;
    const std::vector<BezierPatch>& patches_;
    const TessellationOptions& options_;
    double hull_scale_;
    // What every pass reports alike (d_max, eps1, eps2, tolerance, counts).
    TessellationStats stats_;
    // The coordinates' magnitude and the seam tolerance (find_boundaries).
    double scale_ = 0, seam_tolerance_ = 0;
    // Only a tolerance takes more than one pass: only then is anything kept.
    bool keep_ = false;

    // What the passes share: the split trees and verdicts, the known bounds,
    // the subpatches the next pass splits whatever the criteria say
    // (subpatch_key), and per patch whether it does.
    PatchSubdivision subdivision_;
    FanCertification fans_;
    std::unordered_set<std::uint64_t> split_;
    std::vector<char> changed_;
    // The shared boundaries, a function of the patches and the seam tolerance
    // alone: matched once, in the first pass.
    BoundaryMatch match_;
    bool matched_ = false;
    // The previous pass's arrays: where each patch's subpatches started, its
    // edge registry, rings and their vertices' positions. The next pass copies
    // the parts of patches that cannot have changed (shared_edges.h,
    // subpatch_ring.h). Rings only without seam vertices or aliases (the edge
    // graph's numbers and keys could change).
    struct PreviousPass {
        std::vector<int> leaf_start;
        EdgeRegistry registry;
        bool rings_kept = false;
        SubpatchRings rings;
        std::vector<Vec3> positions; // the rings' vertices (vertex_numbering.h)
    } previous_;

    // The pass under way: its result, clock and progress.
    Tessellation out_;
    std::chrono::steady_clock::time_point start_;
    Lap clock_;
    PassProgress progress_;
};

// Whether the pass after this one splits `sp` (its final fan's bound is above
// the tolerance, when there is one).
inline bool splits_again(const Subpatch& sp, double tolerance, int max_depth) {
    return tolerance > 0 && sp.error_bound > tolerance && sp.depth < max_depth;
}

// Refuses a tessellation past TessellationOptions::max_triangles: throws
// TriangleBudgetError (tessellation.h).
[[noreturn]] void refuse_triangle_budget(const Model& model, const TessellationOptions& options);

} // namespace seamless
