// SPDX-License-Identifier: MIT
// quantise (shading.h) rounds as std::lround of the clamped, scaled
// intensity: halves away from zero, the neighbours of every half level
// included, at 2 to 65536 levels.
#include <seamless/render/shading/shading.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

using namespace seamless;

namespace {
int reference(double intensity, int levels) {
    return static_cast<int>(std::lround(clamp01(intensity) * (levels - 1)));
}
} // namespace

TEST_CASE("quantise rounds as std::lround, halves and their neighbours included", "[shading]") {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> U(-0.25, 1.25);
    for (const int levels : {2, 3, 16, 255, 256, 1000, 65536}) {
        for (int n = 0; n < 20000; ++n) {
            const double I = U(rng);
            REQUIRE(quantise(I, levels) == reference(I, levels));
        }
        // The intensities nearest to each half level (k + 1/2) / (levels - 1).
        for (int k = 0; k + 1 < levels && k < 4000; ++k) {
            const double h = (k + 0.5) / (levels - 1);
            for (double x : {h, std::nextafter(h, 0.0), std::nextafter(h, 1.0)})
                REQUIRE(quantise(x, levels) == reference(x, levels));
        }
    }
    for (const double x : {0.0, -0.0, 1.0, 0.49999999999999994, 0.5, -1e300, 1e300,
                           std::numeric_limits<double>::denorm_min()})
        CHECK(quantise(x, 16) == reference(x, 16));
}
