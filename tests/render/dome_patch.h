// SPDX-License-Identifier: MIT
// Test helper: a bicubic dome in front of the eye (camera coordinates: Z
// forward), its inner control points `bulge` nearer the eye, every coordinate
// jittered by up to 0.05 from rng.
#pragma once

#include <seamless/spline/bezier_patch.h>

#include <random>

namespace seamless::test {

inline BezierPatch random_dome(std::mt19937& rng, double bulge) {
    std::uniform_real_distribution<double> J(-0.05, 0.05);
    BezierPatch b;
    b.p = b.q = 3;
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 3; ++j) {
            const bool inner = (i == 1 || i == 2) && (j == 1 || j == 2);
            b.at(i, j) = HPoint::from({-1 + 2.0 * i / 3 + J(rng), -1 + 2.0 * j / 3 + J(rng),
                                       5 - (inner ? bulge : 0.0) + J(rng)},
                                      1.0);
        }
    return b;
}

} // namespace seamless::test
