// SPDX-License-Identifier: MIT
// A face's surface: an affine one (a parallelogram's bilinear patch) is
// recognised, and over it a flat triangle's distance is largest at a corner,
// which is what lets the refinement measure its triangles at the corners.
#include <tessellate/trimmed/brep_builder.h>

#include <seamless/tessellate/trimmed/face_surface.h>

#include <catch2/catch.hpp>

#include <random>

using namespace seamless;
using namespace seamless::test;

namespace {

// The largest |S(q) - L(q)| over a barycentric grid of the (u,v) triangle
// uv, L the affine map onto the 3D triangle p; and the largest at corners.
std::pair<double, double> flat_distance(const FaceSurface& s, const std::array<Vec3, 3>& uv,
                                        const std::array<Vec3, 3>& p) {
    double inside = 0, corners = 0;
    constexpr int n = 24;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
            const double a = double(i) / n, b = double(j) / n, c = 1 - a - b;
            const Vec3 q = a * uv[0] + b * uv[1] + c * uv[2];
            const double d = distance(s.point(q), a * p[0] + b * p[1] + c * p[2]);
            inside = std::max(inside, d);
            if ((i == n) + (j == n) + (i + j == 0) > 0) corners = std::max(corners, d);
        }
    return {inside, corners};
}

} // namespace

TEST_CASE("face surface: an affine surface's flat triangles are farthest at a corner", "[brep]") {
    const PlaneFrame frame{{1, 2, 3}, {0.6, 0.8, 0}, {0, 0, 1}};
    BSplineSurface plane = frame.surface(-2, 3, 0.5, 4);
    BSplineSurface weighted = plane;
    weighted.weights = {2.5, 2.5, 2.5, 2.5};
    BSplineSurface trapezoid = plane;
    trapezoid.points[3] = trapezoid.points[3] + Vec3{0.6, 0.8, 0}; // still planar, not affine
    CHECK(FaceSurface(plane).affine());
    CHECK(FaceSurface(weighted).affine());
    CHECK_FALSE(FaceSurface(trapezoid).affine());
    CHECK_FALSE(FaceSurface(cylinder_surface({}, 2, 3)).affine());

    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-2, 3), v(0.5, 4), off(-1e-3, 1e-3);
    double trapezoid_excess = 0;
    for (int k = 0; k < 50; ++k) {
        const std::array<Vec3, 3> uv{Vec3{u(rng), v(rng), 0}, Vec3{u(rng), v(rng), 0},
                                     Vec3{u(rng), v(rng), 0}};
        for (const BSplineSurface* surface : {&plane, &weighted, &trapezoid}) {
            const FaceSurface s(*surface);
            // Corners off the surface as boundary points may be, by up to
            // a tolerance.
            std::array<Vec3, 3> p;
            for (int i = 0; i < 3; ++i) p[i] = s.point(uv[i]) + Vec3{off(rng), off(rng), off(rng)};
            const auto [inside, corners] = flat_distance(s, uv, p);
            if (s.affine())
                CHECK(inside <= corners + 1e-12);
            else
                trapezoid_excess = std::max(trapezoid_excess, inside - corners);
        }
    }
    // Not affine: the corners alone would miss the surface's bulge.
    CHECK(trapezoid_excess > 1e-2);
}
