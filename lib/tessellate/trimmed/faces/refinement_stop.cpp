// SPDX-License-Identifier: MIT
#include <seamless/tessellate/trimmed/faces/refinement_stop.h>

#include <algorithm>

namespace seamless {

namespace {

// A face grown past this many triangles stops.
constexpr size_t kStopSize = 4096;
// ... or past this many triangles per boundary point: its refinement has
// then gone on long beside a side it does not mend (a face whose triangles
// meet the limits has a few dozen per boundary point).
constexpr size_t kStopPerBoundaryPoint = 64;
// ... or once it stalls: this many rounds without fewer triangles failing
// than ever before, past this many triangles per boundary point. A
// converging face's failures fall round after round once its first rounds
// (where they rise with the triangles) are over; a face refining beside a
// side it does not mend keeps failing there, and its failures level off and
// rise again as the points it inserts there crowd in.
constexpr int kStallRounds = 4;
constexpr size_t kStallPerBoundaryPoint = 24;

} // namespace

bool RefinementStop::due(int round, size_t failing, size_t triangles) {
    if (failing < fewest_failing_) fewest_failing_ = failing, fewest_round_ = round;
    const bool stalled = round - fewest_round_ >= kStallRounds &&
                         triangles > kStallPerBoundaryPoint * boundary_points_;
    return stalled || triangles > std::min(kStopSize, kStopPerBoundaryPoint * boundary_points_);
}

bool RefinementStop::crowded(size_t triangles) const {
    return triangles > kStopPerBoundaryPoint * boundary_points_;
}

} // namespace seamless
