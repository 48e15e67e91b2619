// SPDX-License-Identifier: MIT
#include <seamless/tessellate/trimmed/bounds/box_hull.h>
#include <spline/patch_samples.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace seamless;
using namespace seamless::test;

TEST_CASE("the box hull bounds a piece against its affine map, corners on or off the patch",
          "[heavy]") {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> in(0, 1), b(0, 1), lift(-0.05, 0.05);
    int finite = 0;
    for (auto [p, q] : {std::pair{1, 1}, {2, 1}, {3, 3}, {9, 9}, {2, 9}})
        for (bool rational : {false, true})
            for (int round = 0; round < 20; ++round) {
                const BezierPatch patch = random_patch(rng, p, q, rational);
                std::array<std::array<double, 2>, 3> st;
                const double size = round % 3 == 0 ? 0.5 : round % 3 == 1 ? 0.1 : 0.01;
                const double s = in(rng) * (1 - size), t = in(rng) * (1 - size);
                for (auto& x : st) x = {s + size * b(rng), t + size * b(rng)};
                if (round % 5 == 4) st[2][0] = st[0][0]; // a vertical side
                std::array<Vec3, 3> L;
                for (int k = 0; k < 3; ++k) {
                    L[k] = evaluate_homogeneous(patch, st[k][0], st[k][1]).point();
                    if (round % 2) L[k] = L[k] + Vec3{lift(rng), lift(rng), lift(rng)};
                }
                BoxNet box;
                restrict_to_box(patch, st, box);
                const double B = box_hull_bound(box, L);
                if (!std::isfinite(B)) continue; // a weight of the random net below 0
                ++finite;
                for (int m = 0; m < 40; ++m) {
                    double l1 = b(rng), l2 = b(rng);
                    if (l1 + l2 > 1) l1 = 1 - l1, l2 = 1 - l2;
                    const double l0 = 1 - l1 - l2;
                    const double ps = l0 * st[0][0] + l1 * st[1][0] + l2 * st[2][0];
                    const double pt = l0 * st[0][1] + l1 * st[1][1] + l2 * st[2][1];
                    const Vec3 S = evaluate_homogeneous(patch, ps, pt).point();
                    INFO("degree " << p << "," << q << " size " << size);
                    REQUIRE(distance(S, l0 * L[0] + l1 * L[1] + l2 * L[2]) <= B);
                }
            }
    CHECK(finite > 100);
}

TEST_CASE("the box hull refuses a piece of no area") {
    std::mt19937_64 rng(37);
    const BezierPatch patch = random_patch(rng, 3, 3, false);
    const std::array<std::array<double, 2>, 3> st{{{0.1, 0.1}, {0.3, 0.3}, {0.5, 0.5}}};
    const std::array<Vec3, 3> L{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{2, 0, 0}};
    BoxNet box;
    restrict_to_box(patch, st, box);
    CHECK(std::isinf(box_hull_bound(box, L)));
}
