// SPDX-License-Identifier: MIT
// exact_point (exact_point.h) is evaluate(b, s, t).point bit for bit: on
// polynomial and rational patches of degrees 3, 2, 1 and mixed, at the
// corners, the centre, dyadic and random parameters.
#include <seamless/model/model.h>
#include <seamless/spline/surface_point.h>

#include <catch2/catch.hpp>

#include "test_util.h"

#include <random>
#include <string>
#include <vector>

using namespace seamless;

TEST_CASE("exact_point is evaluate's point bit for bit", "[exact_point]") {
    int checked = 0;
    bool rational = false, bicubic = false, other = false;
    for (const char* name : {"teapot", "extreme_weights", "sphere", "torus_exact", "bilinear",
                             "quarter_cylinder", "repeated_knot"}) {
        const Model m = load_model(test::model_path(std::string(name) + ".json"));
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(0, 1);
        for (const BezierPatch& b : bezier_patches(m)) {
            rational = rational || b.rational;
            bicubic = bicubic || (b.p == 3 && b.q == 3);
            other = other || b.p != 3 || b.q != 3;
            std::vector<std::array<double, 2>> at = {
                {0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}, {0.25, 0.75}, {0x1p-30, 1 - 0x1p-30}};
            for (int k = 0; k < 40; ++k) at.push_back({u(rng), u(rng)});
            for (const auto& [s, t] : at) {
                INFO(name << " s " << s << " t " << t);
                CHECK(test::same_bytes(exact_point(b, s, t), evaluate(b, s, t).point));
                ++checked;
            }
        }
    }
    CHECK(rational);
    CHECK(bicubic);
    CHECK(other);
    CHECK(checked > 1000);
}
