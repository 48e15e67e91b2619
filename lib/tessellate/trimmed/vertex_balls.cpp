// SPDX-License-Identifier: MIT
#include <seamless/tessellate/trimmed/vertex_balls.h>

#include <algorithm>
#include <cstddef>

namespace seamless {

namespace {

// The ball's radius at most, as a fraction of D.
constexpr double kLargestBall = 0.01;

} // namespace

void drop_points_in_vertex_balls(const BRep& brep, int edge, EdgePolyline& line, double deviation) {
    const double radius = kLargestBall * deviation;
    const BRepEdge& e = brep.edges[edge];
    const size_t n = line.points.size();
    if (e.degenerate() || n < 3) return;
    const BRepVertex& a = brep.vertices[e.start];
    const BRepVertex& b = brep.vertices[e.end];
    const double ra = std::min(a.tolerance, radius), rb = std::min(b.tolerance, radius);
    size_t first = 1, last = n - 1; // the interior points kept: [first, last)
    while (first < last && distance(line.points[first], a.point) <= ra) ++first;
    while (last > first && distance(line.points[last - 1], b.point) <= rb) --last;
    // A closed edge needs three segments to bound anything.
    if ((first == 1 && last == n - 1) || (e.start == e.end && last - first < 2)) return;
    const auto keep = [&](auto& v) {
        v.erase(v.begin() + static_cast<std::ptrdiff_t>(last),
                v.begin() + static_cast<std::ptrdiff_t>(n - 1));
        v.erase(v.begin() + 1, v.begin() + static_cast<std::ptrdiff_t>(first));
    };
    keep(line.t);
    keep(line.points);
}

} // namespace seamless
