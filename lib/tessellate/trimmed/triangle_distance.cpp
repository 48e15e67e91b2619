// SPDX-License-Identifier: MIT
#include <seamless/base/segment_distance.h>
#include <seamless/tessellate/trimmed/triangle_distance.h>

#include <algorithm>
#include <cmath>

namespace seamless {

double point_triangle_distance(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
    const Vec3 n = cross(b - a, c - a);
    const double nn = dot(n, n);
    const double edges = std::min({point_segment_distance(p, a, b), point_segment_distance(p, b, c),
                                   point_segment_distance(p, c, a)});
    if (!(nn > 0)) return edges;
    // Inside the prism over the triangle: the distance to its plane.
    const Vec3 q = p - (dot(p - a, n) / nn) * n;
    const bool inside = dot(cross(b - a, q - a), n) >= 0 && dot(cross(c - b, q - b), n) >= 0 &&
                        dot(cross(a - c, q - c), n) >= 0;
    return inside ? std::abs(dot(p - a, n)) / std::sqrt(nn) : edges;
}

} // namespace seamless
