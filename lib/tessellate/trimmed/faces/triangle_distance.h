// SPDX-License-Identifier: MIT
// Distance of a point to a triangle in 3D: the face's deviation samples
// measure the surface's points against the flat triangle, as the edges'
// measure them against their chords (point_segment_distance).
#pragma once

#include <seamless/base/vec.h>

namespace seamless {

// A triangle prepared for the distances of many points (a face's samples).
class TriangleFrame {
  public:
    TriangleFrame(Vec3 a, Vec3 b, Vec3 c);
    // Euclidean distance of p to the triangle (to its edges when degenerate).
    double distance(Vec3 p) const;

  private:
    Vec3 a_, b_, c_, n_;
    double nn_;
};

// Euclidean distance of p to the triangle abc (to its edges when degenerate).
double point_triangle_distance(Vec3 p, Vec3 a, Vec3 b, Vec3 c);

} // namespace seamless
