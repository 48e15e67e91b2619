// SPDX-License-Identifier: MIT
// Adaptive subdivision of a Bezier patch into planar subpatches (paper section
// 6): de Casteljau halving at the parameter midpoint until the planarity test
// holds. Only the split structure is decided here, by planarity alone; the
// crack-free vertices are placed afterwards (shared_edges.h), once the
// neighbours' splits are known.
#pragma once

#include <seamless/base/key_table.h>
#include <seamless/spline/bezier_patch.h>
#include <seamless/tessellate/subdivision/patch_tree.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <unordered_set>
#include <vector>

namespace seamless {

// Subpatch parameters are dyadic: integers on a 2^30 grid over the patch's
// local [0,1]^2, so split points are exact and comparable across patches.
inline constexpr int kParamBits = 30;
inline constexpr int kParamOne = 1 << kParamBits;
inline double param_of(int i) {
    return static_cast<double>(i) / kParamOne;
}

// [s0, s1] x [t0, t1] on the grid: s along u, t along v.
struct ParamRect {
    int s0 = 0, s1 = kParamOne, t0 = 0, t1 = kParamOne;
    friend bool operator==(const ParamRect&, const ParamRect&) = default;
};

// The tolerance and angle criteria's verdict on one subpatch (subpatch_key ->
// verdict), kept between the passes of a tolerance (tessellation_pass.h): the
// criteria depend on the subpatch alone, so a later pass asks only about
// subpatches it has not met. A key collision can only change where the
// subdivision splits; the final certified bound is computed afresh.
struct FanVerdict {
    bool accepted = false;
    double fan_error = -1;
};
using FanMemo = KeyTable<FanVerdict>;

// A fan whose corners lie within this fraction of the tolerance of its
// centre is too small for the angle criterion (the subdivision's fans and
// the two-triangle subpatches, fan_certification.h).
inline constexpr double kTinyFan = 1.0 / 8;

struct SubdivisionOptions {
    // Planarity tolerances, model units (section 8); infinity: not tested.
    double eps1 = 0, eps2 = 0;
    int max_depth = 24; // safeguard: at most this many halvings per patch
    // > 0: also split until the certified fan bound (error_bound.h) is at most
    // this, model units.
    double tolerance = 0;
    // > 0: also split until every fan triangle's normal is within angle / 2 of
    // the surface normals at its three parameter corners (radians), so that two
    // triangles meeting at a surface vertex differ by at most `angle`.
    double angle = 0;
    // Subpatches to split whatever the criteria say (subpatch_key): those a
    // previous pass left above the tolerance. Not owned; may be null.
    const std::unordered_set<std::uint64_t>* split = nullptr;
    // Verdicts of earlier passes, read and extended. Not owned; may be null.
    FanMemo* memo = nullptr;
    // false: no tree nodes are written (trees.nodes stays empty; node ids, as
    // Subpatch::node, still count them in the same pre-order): for a caller
    // that wants no patch trees (TessellationOptions::patch_trees).
    bool nodes = true;
    // The subpatches a budget still allows (TessellationOptions::max_triangles),
    // shared by the workers of a pass and counted down by their leaves (in
    // batches of kLeafBatch, the rest when subdivide returns); once it is below
    // zero no subpatch is split further and the caller refuses the pass
    // (PatchSubdivision::subdivide). Not owned; null: no budget.
    std::atomic<std::int64_t>* leaves_left = nullptr;
};

// A leaf of the split tree: a planar subpatch (or one stopped by max_depth).
struct Subpatch {
    int patch = -1; // index into bezier_patches(model)
    int node = -1;  // its node in PatchTrees
    ParamRect rect;
    int depth = 0;
    bool planar = true; // false when max_depth stopped the subdivision
    // The subpatch's corner points (order of BezierPatch::corner), its centre
    // S(1/2, 1/2), and (with a tolerance, else 0) the fan_bound (error_bound.h)
    // for the four triangles from that centre over those corners that accepted it.
    std::array<Vec3, 4> corners{};
    Vec3 centre;
    double fan_error = 0;
    // Filled by the triangulation: its fan triangles and their error bound.
    int first_triangle = 0, triangle_count = 0;
    double error_bound = 0;
    // With a tolerance, where the ring is the four corners alone: the two
    // triangles split along corners 0-2 (0) or 1-3 (1) in place of the fan,
    // when they meet the tolerance and angle (fan_certification.h); -1: the fan.
    signed char diagonal = -1;
};

// Identity of the subpatch `r` of patch `patch` (a hash: a collision only
// splits one more subpatch).
std::uint64_t subpatch_key(int patch, const ParamRect& r);

// Splits `patch` (index `patch_index`) recursively, appending its tree's nodes
// to `trees.nodes` (root first) and its planar subpatches to `out`; returns the
// root node. A subpatch is a leaf when it passes every criterion of `options`
// (planarity, tolerance, angle) or max_depth stops it. The direction split is
// the less flat one (flatness_u/v); on a tie (within a factor 2) the one whose
// corner edges are longer. A subpatch the tolerance's fan bound rejected (or a
// later pass forces) is halved where its second derivative bound is larger
// (second_derivative_bounds, error_bound.h): flatness alone never splits a
// straight but unevenly parametrised direction, whose drift then keeps the
// bound above any tolerance (bug28366_fuselage's cylinder).
int subdivide(const BezierPatch& patch, int patch_index, const SubdivisionOptions& options,
              PatchTrees& trees, std::vector<Subpatch>& out);

} // namespace seamless
