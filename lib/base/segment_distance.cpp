// SPDX-License-Identifier: MIT
#include <seamless/base/segment_distance.h>

#include <algorithm>

namespace seamless {

double point_segment_distance(Vec3 p, Vec3 a, Vec3 b) {
    const Vec3 d = b - a;
    const double dd = dot(d, d);
    if (!(dd > 0)) return distance(p, a);
    const double t = std::clamp(dot(p - a, d) / dd, 0.0, 1.0);
    return distance(p, a + t * d);
}

} // namespace seamless
