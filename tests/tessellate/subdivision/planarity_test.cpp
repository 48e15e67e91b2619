// SPDX-License-Identifier: MIT
// Planarity test (paper section 6) on flat, curved and degenerate patches.
#include <seamless/tessellate/subdivision/planarity.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace seamless;

namespace {

template <class F> BezierPatch make_patch(int p, int q, F&& f) {
    BezierPatch b;
    b.p = p;
    b.q = q;
    for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j) b.at(i, j) = HPoint::from(f(double(i) / p, double(j) / q), 1);
    return b;
}

} // namespace

TEST_CASE("a flat patch is planar, also when tilted and unevenly spaced", "[planarity]") {
    const BezierPatch b = make_patch(3, 3, [](double s, double t) {
        const double x = s * s + 0.3 * s, y = t + 0.1 * s * t;
        return Vec3{x, y, 0.5 * x - 0.25 * y + 1};
    });
    const Planarity pl = planarity(b);
    CHECK(pl.plane < 1e-14);
    CHECK(pl.boundary > 0.01); // the s = 0 .. 1 rows are bent inside the plane
    CHECK(is_planar(b, 1e-9, 1.0));
    CHECK_FALSE(is_planar(b, 1e-9, 1e-3));
}

TEST_CASE("a curved patch fails the plane test until the tolerance exceeds its bulge",
          "[planarity]") {
    const BezierPatch b = make_patch(3, 3, [](double s, double t) {
        return Vec3{s, t, 0.2 * s * (1 - s)};
    });
    const Planarity pl = planarity(b);
    // Inner control points (made from z = 0.2 s (1 - s) at s = 1/3, 2/3) are
    // 0.2 * 2/9 off the corners' plane.
    CHECK(pl.plane == Approx(0.2 * 2 / 9));
    CHECK_FALSE(is_planar(b, 0.04, 1));
    CHECK(is_planar(b, 0.05, 1));
    CHECK(flatness_u(b) > 0.04);
    CHECK(flatness_v(b) < 1e-15);
}

TEST_CASE("a twisted bilinear patch has straight boundaries but is not planar", "[planarity]") {
    const BezierPatch b = make_patch(1, 1, [](double s, double t) { return Vec3{s, t, s * t}; });
    const Planarity pl = planarity(b);
    CHECK(pl.boundary == 0);
    CHECK(pl.plane > 0.5);
    CHECK_FALSE(is_planar(b, 0.1, 0.1));
}

TEST_CASE("a patch with a collapsed edge (pole) is measured without division by zero",
          "[planarity]") {
    // Edge s = 0 collapsed to the apex of a cone-like cap.
    const BezierPatch b = make_patch(3, 3, [](double s, double t) {
        const double a = 1.5 * t;
        return Vec3{s * std::cos(a), s * std::sin(a), 1 - s * s};
    });
    REQUIRE(b.corner(0) == b.corner(3));
    const Planarity pl = planarity(b);
    CHECK(std::isfinite(pl.plane));
    CHECK(std::isfinite(pl.boundary));
    CHECK(pl.plane > 0.1);
    CHECK_FALSE(is_planar(b, 0.01, 0.2));
}

TEST_CASE("coincident or collinear corners: the plane test needs all points near them",
          "[planarity]") {
    // All four corners at the origin, interior control points off it.
    const BezierPatch lump = make_patch(3, 3, [](double s, double t) {
        const double bump = s * (1 - s) * t * (1 - t);
        return Vec3{bump, 2 * bump, 0};
    });
    const Planarity pl = planarity(lump);
    CHECK(std::isfinite(pl.plane));
    CHECK(pl.plane > 0.01);
    CHECK_FALSE(is_planar(lump, 0.01, 1));
    // A patch collapsed entirely to one point is planar.
    const BezierPatch point = make_patch(2, 2, [](double, double) { return Vec3{1, 2, 3}; });
    CHECK(is_planar(point, 1e-12, 1e-12));
    // Collinear corners, a straight ribbon: planar; lifted interior points: not.
    const BezierPatch line = make_patch(3, 1, [](double s, double) { return Vec3{s, 0, 0}; });
    CHECK(is_planar(line, 1e-12, 1e-12));
    BezierPatch lifted = line;
    lifted.at(1, 0) = HPoint::from({1.0 / 3, 0.5, 0}, 1);
    CHECK_FALSE(is_planar(lifted, 0.1, 1));
}
