// SPDX-License-Identifier: MIT
// When a face's refinement stops beside boundary sides it does not mend
// (FaceCriteria::stop_when_encroached, face_triangulation.h): a side found
// encroached in kPersistentEncroachment rounds is halved by a re-split round
// and the face redone, so refining the face further only makes triangles
// the redo throws away. A small face's refinement costs little, and left
// alone it mends most encroachments: only a face grown large, or one whose
// refinement has stalled, stops.
#pragma once

#include <cstddef>
#include <cstdint>

namespace seamless {

// Rounds a boundary side must be found encroached in before it counts as
// one refinement does not mend.
inline constexpr int kPersistentEncroachment = 8;

class RefinementStop {
  public:
    explicit RefinementStop(int boundary_points)
        : boundary_points_(static_cast<size_t>(boundary_points)) {}
    // After refinement round `round` (each round once, in order) found
    // `failing` of its `triangles` failing: whether the face has grown or
    // stalled enough to stop once a side is persistently encroached.
    bool due(int round, size_t failing, size_t triangles);
    // More triangles per boundary point than converged faces have: its
    // interior points would crowd a redo (FaceMesh::crowded).
    bool crowded(size_t triangles) const;

  private:
    size_t boundary_points_;
    size_t fewest_failing_ = SIZE_MAX;
    int fewest_round_ = 0; // the round that had them
};

} // namespace seamless
