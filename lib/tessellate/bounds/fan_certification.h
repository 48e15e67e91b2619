// SPDX-License-Identifier: MIT
// Step (d2) of a tessellation pass: every fan's certified two-way distance to
// its subpatch (error_bound.h), each on its own, in parallel; a bound of an
// earlier pass for the same subpatch, centre and ring is reused. With a
// tolerance, a subpatch whose ring is its four corners becomes two triangles
// where they meet the tolerance and the angle (Subpatch::diagonal).
#pragma once

#include <seamless/base/key_table.h>
#include <seamless/spline/bezier_patch.h>
#include <seamless/tessellate/bounds/error_bound.h>
#include <seamless/tessellate/fans/subpatch_ring.h>
#include <seamless/tessellate/subdivision/subdivision.h>

#include <cstdint>
#include <vector>

namespace seamless {

class PassProgress;

// A certified fan bound (error_bound.h) of an earlier pass, with the ring it
// was computed for (ring_size points from ring_first in KnownBounds::rings):
// the bound is a function of the subpatch and its ring.
struct KnownBound {
    ParamRect rect;
    int ring_first = 0, ring_size = 0;
    Vec3 centre;
    double bound = 0;
    signed char diagonal = -1; // Subpatch::diagonal
};
// One patch's known bounds by subpatch_key, their rings end to end.
struct KnownBounds {
    KeyTable<KnownBound> bounds;
    std::vector<RingPoint> rings;
};

// The fans' certified bounds over the passes of a tolerance, with each
// patch's known bounds (the earlier passes').
class FanCertification {
  public:
    // `scale` and `tolerance` as certified_fan_bound's; `angle` (radians, 0:
    // none) as TessellationOptions::angle.
    FanCertification(const std::vector<BezierPatch>& patches, double scale, double tolerance,
                     double angle, int threads)
        : patches_(patches), scale_(scale), tolerance_(tolerance), angle_(angle), threads_(threads),
          known_(patches.size()) {}

    // Subpatch::error_bound and diagonal of every subpatch, from its ring and centre vertex
    // (rings.vertices[].vertex, rings.centre into `positions`); per subpatch,
    // whether its bound was computed (not known from an earlier pass).
    // `same` (may be null): per patch, whether its subpatches, rings and
    // vertex positions are the previous pass's (subpatch_ring.h,
    // PreviousRings), so that each subpatch's known bound is its own, found by
    // key alone (every pass that another follows leaves each subpatch's bound
    // under its key, keep).
    std::vector<char> certify(const SubpatchRings& rings, const std::vector<Vec3>& positions,
                              const std::vector<char>* same, std::vector<Subpatch>& subpatches,
                              const PassProgress* progress = nullptr) const;

    // The `fresh` bounds kept for the next pass, each patch's map on its own,
    // in parallel (`leaf_start`: where each patch's subpatches start, one more
    // entry: the end). With their rings only where `compared` (null: every
    // patch) says the next pass may compare rings: a patch whose subpatches
    // the next pass takes as they are finds its bounds by key alone; a bound
    // kept without its ring is computed again if it is needed after all (the
    // same value: a bound is a function of the subpatch and its ring), and
    // the rings not kept are pages not touched.
    void keep(const SubpatchRings& rings, const std::vector<Vec3>& positions,
              const std::vector<int>& leaf_start, const std::vector<char>& fresh,
              const std::vector<char>* compared, const std::vector<Subpatch>& subpatches);

    // Frees patch p's known bounds (no pass follows).
    void release(int p) { known_[p] = KnownBounds(); }

  private:
    const std::vector<BezierPatch>& patches_;
    double scale_, tolerance_, angle_;
    int threads_;
    std::vector<KnownBounds> known_;
};

} // namespace seamless
