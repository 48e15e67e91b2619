// SPDX-License-Identifier: MIT
#include <seamless/base/segment_distance.h>
#include <seamless/tessellate/trimmed/faces/triangle_distance.h>

#include <algorithm>
#include <cmath>

namespace seamless {

TriangleFrame::TriangleFrame(Vec3 a, Vec3 b, Vec3 c) : corner_{a, b, c} {
    const Vec3 n = cross(b - a, c - a);
    const double nn = dot(n, n);
    flat_ = nn > 0 && std::isfinite(nn);
    if (!flat_) return;
    unit_ = n / std::sqrt(nn);
    // (x - a) . (n x (b - a)) = ((b - a) x (x - a)) . n: non-negative on the
    // triangle's side of ab.
    for (int k = 0; k < 3; ++k) side_[k] = cross(n, corner_[(k + 1) % 3] - corner_[k]);
}

double TriangleFrame::distance(Vec3 p) const {
    if (!flat_)
        return std::min({point_segment_distance(p, corner_[0], corner_[1]),
                         point_segment_distance(p, corner_[1], corner_[2]),
                         point_segment_distance(p, corner_[2], corner_[0])});
    // Inside the prism over the triangle: the distance to its plane. Else
    // the nearest point is on a side whose plane p is beyond (the triangle
    // is convex).
    double nearest = INFINITY;
    for (int k = 0; k < 3; ++k)
        if (dot(p - corner_[k], side_[k]) < 0)
            nearest =
                std::min(nearest, point_segment_distance(p, corner_[k], corner_[(k + 1) % 3]));
    return nearest < INFINITY ? nearest : std::abs(dot(p - corner_[0], unit_));
}

double point_triangle_distance(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
    return TriangleFrame(a, b, c).distance(p);
}

} // namespace seamless
