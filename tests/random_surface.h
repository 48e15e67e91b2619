// SPDX-License-Identifier: MIT
// Random B-spline surfaces for property tests: any degree, clamped or not,
// rational or not, with repeated interior knots now and then.
#pragma once

#include <seamless/spline/bspline_surface.h>

#include <algorithm>
#include <random>

namespace seamless::test {

struct RandomSurfaceOptions {
    int degree_u = 3, degree_v = 3;
    bool clamped = true;
    bool rational = false;
};

inline std::vector<double> random_knots(std::mt19937& rng, int degree, int n, bool clamped) {
    std::uniform_real_distribution<double> U(-2.0, 3.0);
    std::vector<double> k(static_cast<size_t>(n + degree + 1));
    for (double& x : k) x = U(rng);
    std::sort(k.begin(), k.end());
    // Repeat some interior knots (multiplicity up to the degree).
    std::uniform_int_distribution<int> pick(degree + 1, std::max(degree + 1, n - 1));
    if (n > degree + 2 && rng() % 2) {
        int at = pick(rng);
        for (int r = 1; r < degree && at + r < n; ++r) k[at + r] = k[at];
    }
    if (clamped) {
        for (int r = 0; r < degree; ++r) k[r] = k[degree];
        for (int r = 1; r <= degree; ++r) k[n + r] = k[n];
    }
    return k;
}

inline BSplineSurface random_surface(std::mt19937& rng, const RandomSurfaceOptions& o) {
    std::uniform_real_distribution<double> P(-1.0, 1.0), W(0.2, 5.0);
    std::uniform_int_distribution<int> extra(0, 4);
    BSplineSurface s;
    s.name = "random";
    s.degree_u = o.degree_u;
    s.degree_v = o.degree_v;
    s.size_u = o.degree_u + 1 + extra(rng);
    s.size_v = o.degree_v + 1 + extra(rng);
    s.knots_u = random_knots(rng, s.degree_u, s.size_u, o.clamped);
    s.knots_v = random_knots(rng, s.degree_v, s.size_v, o.clamped);
    for (int k = 0; k < s.size_u * s.size_v; ++k) {
        s.points.push_back({P(rng), P(rng), P(rng)});
        if (o.rational) s.weights.push_back(W(rng));
    }
    return s;
}

} // namespace seamless::test
