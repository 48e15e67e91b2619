// SPDX-License-Identifier: MIT
// The differenced control net and its bounds (net_bounds.h): a one-weight
// bicubic net holds exactly the differences of its points, and split_bounds
// does not depend on the order of the differences (what lets it take them
// two or four at a time, SSE2 or AVX2, with the same result).
#include <seamless/tessellate/bounds/net_bounds.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

using namespace seamless;

namespace {

bool same_bits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

bool same_bits(const DerivativeBounds& a, const DerivativeBounds& b) {
    return same_bits(a.A, b.A) && same_bits(a.B, b.B) && same_bits(a.C, b.C);
}

BezierPatch random_bicubic(std::mt19937& rng, double w) {
    std::uniform_real_distribution<double> u(-3, 3);
    BezierPatch b;
    b.rational = w != 1;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) b.at(i, j) = HPoint::from({u(rng), u(rng), u(rng)}, w);
    return b;
}

} // namespace

TEST_CASE("a one-weight bicubic net holds the differences of its points", "[net_bounds]") {
    std::mt19937 rng(11);
    for (double w : {1.0, 2.5}) {
        const BezierPatch b = random_bicubic(rng, w);
        const Vec3 c{0.25, -1.5, 2};
        for (const Net& n : {net_of(b, c), box_net(b, 0, 1, 0, 1, c)}) {
            auto X = [&](int i, int j) { return b.at(i, j).xyz() - b.at(i, j).w * c; };
            CHECK(n.count[Net::kP0] == 0);
            CHECK(n.count[Net::kXs] == 0);
            CHECK(n.count[Net::kXt] == 0);
            REQUIRE(n.count[Net::kXss] == 8);
            REQUIRE(n.count[Net::kXtt] == 8);
            REQUIRE(n.count[Net::kXst] == 9);
            CHECK(n.wlo == w);
            int ss = 0, tt = 0, st = 0;
            for (int i = 0; i <= 3; ++i)
                for (int j = 0; j <= 3; ++j) {
                    if (i + 1 < 3)
                        CHECK(n.at(Net::kXss, ss++) == X(i + 2, j) - 2 * X(i + 1, j) + X(i, j));
                    if (j + 1 < 3)
                        CHECK(n.at(Net::kXtt, tt++) == X(i, j + 2) - 2 * X(i, j + 1) + X(i, j));
                    if (i < 3 && j < 3)
                        CHECK(n.at(Net::kXst, st++) ==
                              X(i + 1, j + 1) - X(i + 1, j) - X(i, j + 1) + X(i, j));
                }
        }
    }
}

TEST_CASE("split_bounds does not depend on the order of the differences", "[net_bounds]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 50; ++trial) {
        // Groups of every length from 0 to 11: full vectors and every tail.
        std::vector<std::pair<Net::Group, Vec3>> diffs;
        for (Net::Group g : {Net::kXss, Net::kXst, Net::kXtt})
            for (int k = 0, count = (trial + 4 * g) % 12; k < count; ++k)
                diffs.push_back({g, {u(rng), u(rng), u(rng)}});
        Net a, b;
        for (const auto& [g, v] : diffs) a.add(g, v);
        std::shuffle(diffs.begin(), diffs.end(), rng);
        for (const auto& [g, v] : diffs) b.add(g, v);
        a.p = a.q = b.p = b.q = 3;
        const Vec3 n = normalize(Vec3{u(rng), u(rng), u(rng)});
        const SplitBounds sa = split_bounds(a, n), sb = split_bounds(b, n);
        CHECK(same_bits(sa.normal, sb.normal));
        CHECK(same_bits(sa.tangential, sb.tangential));
        CHECK(same_bits(derivative_bounds(a).A, derivative_bounds(b).A));
    }
}
