// SPDX-License-Identifier: MIT
// Bezier clipping's coefficient hulls and difference ranges on lane pairs
// (interval/lanes.h) equal the scalar interval code bit for bit, on random
// subpatch coefficients of every shape, magnitude and sign; beyond the lanes'
// magnitude limit clip_cluster takes the scalar code.
#include <seamless/render/subscreen/bezier_clip.h>

#include <catch2/catch.hpp>

#include "interval/lanes_random.h"

#include <vector>

using namespace seamless;

namespace {

std::vector<Interval> random_coefficients(std::mt19937& rng, SubpatchShape sh, int max_exp) {
    std::vector<Interval> c(sh.size());
    for (Interval& x : c) x = test::random_magnitude_interval(rng, max_exp);
    return c;
}

} // namespace

TEST_CASE("Lane clipping ranges equal the scalar ones bit for bit",
          "[primary_cluster][lanes][heavy]") {
    constexpr int K = BezierPatch::kMaxOrder;
    std::mt19937 rng(77);
    std::uniform_int_distribution<int> deg(0, K - 1), dim(3, 4);
    int lane_cases = 0;
    for (int n = 0; n < 20000; ++n) {
        const SubpatchShape sh{deg(rng), deg(rng), dim(rng)};
        const std::vector<Interval> c = random_coefficients(rng, sh, 500);
        const Interval a = test::random_magnitude_interval(rng, 500);
        const Interval b = test::random_magnitude_interval(rng, 500);
        REQUIRE(cluster_lanes_apply(c.data(), sh, a, b));
        ++lane_cases;
        // Both rows' differences at once equal difference_ranges per row.
        IMat<2> D[2];
        for (int l = 0; l < 2; ++l) cluster_differences(c.data(), sh, a, b, D[l], l == 1);
        for (int k = 0; k < 2; ++k) {
            const Interval e = k == 0 ? a : b;
            Interval col[2][K], row[2][K], du[2], dv[2];
            for (int l = 0; l < 2; ++l) {
                coefficient_hulls(c.data(), sh, e, k, col[l], row[l], l == 1);
                difference_ranges(c.data(), sh, e, k, du[l], dv[l], l == 1);
            }
            INFO("shape " << sh.p << "x" << sh.q << " dim " << sh.dim << " k " << k << " e " << e);
            for (int i = 0; i <= sh.p; ++i) REQUIRE(test::same_bits(col[0][i], col[1][i]));
            for (int j = 0; j <= sh.q; ++j) REQUIRE(test::same_bits(row[0][j], row[1][j]));
            REQUIRE(test::same_bits(du[0], du[1]));
            REQUIRE(test::same_bits(dv[0], dv[1]));
            for (int l = 0; l < 2; ++l) {
                REQUIRE(test::same_bits(D[l](k, 0), du[0]));
                REQUIRE(test::same_bits(D[l](k, 1), dv[0]));
            }
        }
    }
    CHECK(lane_cases == 20000);
}

TEST_CASE("Huge coefficients take the scalar clipping path", "[primary_cluster][lanes]") {
    std::mt19937 rng(5);
    const SubpatchShape sh{3, 2, 3};
    for (double huge : {0x1p500, -0x1p900, std::numeric_limits<double>::infinity()}) {
        std::vector<Interval> c = random_coefficients(rng, sh, 20);
        const Interval a(-0.1, 0.2), b(0.3, 0.4);
        REQUIRE(cluster_lanes_apply(c.data(), sh, a, b));
        CHECK_FALSE(cluster_lanes_apply(c.data(), sh, Interval(-1.0, huge), b));
        c[sh.index(2, 1, 1)] = Interval::hull(1.0, huge);
        CHECK_FALSE(cluster_lanes_apply(c.data(), sh, a, b));
        // The scalar path still encloses G_0 at every coefficient: the column
        // hulls hold x - e z for sample points e, x, z of their intervals.
        Interval col[BezierPatch::kMaxOrder], row[BezierPatch::kMaxOrder];
        coefficient_hulls(c.data(), sh, a, 0, col, row, false);
        for (int i = 0; i <= sh.p; ++i)
            for (int j = 0; j <= sh.q; ++j) {
                const Interval x = c[sh.index(0, i, j)], z = c[sh.index(2, i, j)];
                if (!std::isfinite(z.hi())) continue;
                const double g = x.lo() - a.hi() * z.hi();
                if (std::isfinite(g)) CHECK((col[i].contains(g) || !std::isfinite(col[i].lo())));
            }
    }
}
