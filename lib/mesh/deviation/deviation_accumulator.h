// SPDX-License-Identifier: MIT
// Pieces both deviation measures share: the running max and sum of squares
// of one fixed chunk of samples, combined in chunk order into DeviationStats
// (the same sums, bit for bit, whatever the thread count), and the
// barycentric points they sample triangles at.
#pragma once

#include <seamless/mesh/deviation/deviation.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace seamless {

struct DeviationAccumulator {
    double max = 0, sum_sq = 0;
    long long count = 0;
    Vec3 at; // the sample of the largest distance (the first, in chunk order)
    void add(double d, Vec3 x = {}) {
        if (d > max) max = d, at = x;
        sum_sq += d * d;
        ++count;
    }
    void add(const DeviationAccumulator& c) {
        if (c.max > max) max = c.max, at = c.at;
        sum_sq += c.sum_sq;
        count += c.count;
    }
};

inline DeviationStats combine(const std::vector<DeviationAccumulator>& chunks) {
    DeviationAccumulator a;
    for (const DeviationAccumulator& c : chunks) a.add(c);
    DeviationStats s;
    s.max = a.max;
    s.at = a.at;
    s.samples = a.count;
    s.rms = a.count > 0 ? std::sqrt(a.sum_sq / static_cast<double>(a.count)) : 0.0;
    return s;
}

// Barycentric weights (i, j, k) / level with i + j + k = level (2: corners and
// edge midpoints), plus the centroid where the level does not hold it.
inline std::vector<std::array<double, 3>> barycentric_points(int level) {
    level = std::max(1, level);
    std::vector<std::array<double, 3>> w;
    for (int i = 0; i <= level; ++i)
        for (int j = 0; i + j <= level; ++j)
            w.push_back({double(i) / level, double(j) / level, double(level - i - j) / level});
    if (level % 3 != 0) w.push_back({1.0 / 3, 1.0 / 3, 1.0 / 3});
    return w;
}

} // namespace seamless
