// SPDX-License-Identifier: MIT
// Distance of a point to a triangle in 3D: the face's deviation samples
// measure the surface's points against the flat triangle, as the edges'
// measure them against their chords (point_segment_distance).
#pragma once

#include <seamless/base/vec.h>

#include <array>

namespace seamless {

// A triangle prepared for the distances of many points (a face's samples):
// its unit normal and the inward normals of its sides' planes through the
// normal, so that a point costs four dot products where its foot falls
// inside.
class TriangleFrame {
  public:
    TriangleFrame(Vec3 a, Vec3 b, Vec3 c);
    // Euclidean distance of p to the triangle (to its edges when degenerate).
    double distance(Vec3 p) const;

  private:
    std::array<Vec3, 3> corner_, side_;
    Vec3 unit_;
    bool flat_ = false; // has a normal
};

// Euclidean distance of p to the triangle abc (to its edges when degenerate).
double point_triangle_distance(Vec3 p, Vec3 a, Vec3 b, Vec3 c);

} // namespace seamless
