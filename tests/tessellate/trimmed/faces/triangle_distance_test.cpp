// SPDX-License-Identifier: MIT
// Point-triangle distance (triangle_distance.h) against the nearest of a
// fine barycentric grid of the triangle: never above it, and within the
// grid's spacing below it; degenerate triangles measure to their edges.
#include <seamless/base/segment_distance.h>
#include <seamless/tessellate/trimmed/faces/triangle_distance.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace seamless;

namespace {

Vec3 random_point(std::mt19937& rng, double scale) {
    std::uniform_real_distribution<double> u(-scale, scale);
    return {u(rng), u(rng), u(rng)};
}

// The nearest point of an n-step barycentric grid, and the grid's spacing.
std::pair<double, double> grid_distance(Vec3 p, Vec3 a, Vec3 b, Vec3 c, int n) {
    double best = INFINITY;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
            const double s = double(i) / n, t = double(j) / n;
            best = std::min(best, distance(p, a + s * (b - a) + t * (c - a)));
        }
    const double spacing = std::max({distance(a, b), distance(b, c), distance(c, a)}) / n;
    return {best, spacing};
}

} // namespace

TEST_CASE("triangle distance: between the exact nearest point and a fine grid's", "[brep]") {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 400; ++trial) {
        const Vec3 a = random_point(rng, 1), b = random_point(rng, 1), c = random_point(rng, 1);
        const TriangleFrame frame(a, b, c);
        for (int k = 0; k < 5; ++k) {
            // Points near the plane too, where the prism test decides.
            const Vec3 p = k < 2 ? (a + b + c) / 3.0 + random_point(rng, 1.5)
                                 : a + 0.7 * (b - a) + 0.6 * (c - a) + random_point(rng, 0.05);
            const double d = frame.distance(p);
            const auto [grid, spacing] = grid_distance(p, a, b, c, 200);
            INFO("trial " << trial << " point " << k);
            REQUIRE(d <= grid + 1e-12);
            REQUIRE(d >= grid - spacing);
            REQUIRE(d == point_triangle_distance(p, a, b, c));
        }
    }
}

TEST_CASE("triangle distance: a degenerate triangle measures to its edges", "[brep]") {
    const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{2, 0, 0}, p{0.5, 1, 0};
    CHECK(TriangleFrame(a, b, c).distance(p) == point_segment_distance(p, a, c));
    CHECK(TriangleFrame(a, a, a).distance(p) == distance(p, a));
}
