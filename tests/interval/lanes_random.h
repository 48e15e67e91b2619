// SPDX-License-Identifier: MIT
// Random intervals over all magnitudes and signs for the bit-for-bit tests of
// the lane pairs (interval/lanes.h): bounds 0, -0 or +-m 2^E with E from the
// subnormals up to below `max_exp`, thin intervals and zero bounds included.
#pragma once

#include <seamless/interval/interval.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

namespace seamless::test {

inline double random_magnitude_value(std::mt19937& rng, int max_exp) {
    std::uniform_int_distribution<int> kind(0, 15), ex(-1074, max_exp - 1);
    std::uniform_real_distribution<double> m(1.0, 2.0);
    const int k = kind(rng);
    if (k == 0) return 0.0;
    if (k == 1) return -0.0;
    const double v = std::ldexp(m(rng), k < 8 ? ex(rng) : ex(rng) / 16); // half near 1
    return k % 2 == 0 ? v : -v;
}

inline Interval random_magnitude_interval(std::mt19937& rng, int max_exp) {
    const double a = random_magnitude_value(rng, max_exp);
    if (std::uniform_int_distribution<int>(0, 7)(rng) == 0) return Interval(a); // thin
    return Interval::hull(a, random_magnitude_value(rng, max_exp));
}

// Same bits in both bounds (so -0 and +0 differ).
inline bool same_bits(Interval x, Interval y) {
    return std::bit_cast<std::uint64_t>(x.lo()) == std::bit_cast<std::uint64_t>(y.lo()) &&
           std::bit_cast<std::uint64_t>(x.hi()) == std::bit_cast<std::uint64_t>(y.hi());
}

} // namespace seamless::test
