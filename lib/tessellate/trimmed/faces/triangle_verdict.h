// SPDX-License-Identifier: MIT
// A triangle's verdict (face_triangulation.h: within the deviation and the
// angle, or to split), and the verdicts a face's run accepted, kept by their
// corners' (u,v) points for a redo of the face from the run's points
// (face_seeds.h). A verdict is a function of the triangle's corners (their
// (u,v) and 3D points and normals), of which sides lie on the boundary and
// of the face's scale and tolerance; wherever a re-split left the
// triangulation as it was, the redo meets the same triangles and takes
// their verdicts instead of judging them again.
#pragma once

#include <seamless/base/vec.h>

#include <array>
#include <vector>

namespace seamless {

struct TriangleVerdict {
    bool drop = false;  // two corners one mesh vertex (pole, seam): zero area, left out
    bool split = false; // above the deviation or angle, or flat on the surface
    double deviation = 0;
    double badness = 0; // the largest of deviation and angle over their limits
    std::array<Vec3, 3> normals;
};

class AcceptedTriangles {
  public:
    // A triangle with corners uv (counter-clockwise in the domain) and
    // boundary[k] for the side opposite corner k; `v` not split.
    void add(const std::array<Vec3, 3>& uv, const std::array<bool, 3>& boundary,
             const TriangleVerdict& v);
    void seal(); // after the last add, before find
    // The verdict of the triangle with these corners (in any rotation) and
    // sides, in their order, when one was added.
    bool find(const std::array<Vec3, 3>& uv, const std::array<bool, 3>& boundary,
              TriangleVerdict& v) const;
    bool empty() const { return entries_.empty(); }
    size_t size() const { return entries_.size(); }

  private:
    struct Entry {
        std::array<double, 6> key; // the corners' (u, v) from the least corner on
        std::array<bool, 3> boundary;
        std::array<Vec3, 3> normals;
        double deviation = 0;
        bool drop = false;
    };
    std::vector<Entry> entries_;
};

} // namespace seamless
