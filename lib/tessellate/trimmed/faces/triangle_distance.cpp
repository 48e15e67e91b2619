// SPDX-License-Identifier: MIT
#include <seamless/base/segment_distance.h>
#include <seamless/tessellate/trimmed/faces/triangle_distance.h>

#include <algorithm>
#include <cmath>

namespace seamless {

TriangleFrame::TriangleFrame(Vec3 a, Vec3 b, Vec3 c)
    : a_(a), b_(b), c_(c), n_(cross(b - a, c - a)), nn_(dot(n_, n_)) {}

double TriangleFrame::distance(Vec3 p) const {
    if (nn_ > 0) {
        // Inside the prism over the triangle: the distance to its plane.
        const double h = dot(p - a_, n_);
        const Vec3 q = p - (h / nn_) * n_;
        if (dot(cross(b_ - a_, q - a_), n_) >= 0 && dot(cross(c_ - b_, q - b_), n_) >= 0 &&
            dot(cross(a_ - c_, q - c_), n_) >= 0)
            return std::abs(h) / std::sqrt(nn_);
    }
    return std::min({point_segment_distance(p, a_, b_), point_segment_distance(p, b_, c_),
                     point_segment_distance(p, c_, a_)});
}

double point_triangle_distance(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
    return TriangleFrame(a, b, c).distance(p);
}

} // namespace seamless
