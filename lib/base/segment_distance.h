// SPDX-License-Identifier: MIT
// Distance of a point to a segment, for the planarity test (section 6) and
// the mesh check's T-junctions and slivers.
#pragma once

#include <seamless/base/vec.h>

namespace seamless {

// Euclidean distance of p to the segment [a, b] (to a when a == b).
double point_segment_distance(Vec3 p, Vec3 a, Vec3 b);

} // namespace seamless
