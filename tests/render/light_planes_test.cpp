// SPDX-License-Identifier: MIT
// Light planes formed on first use (light_planes.h): each is apex_triangle's,
// bit for bit, whichever thread formed it and whether it was kept or not; a
// copy keeps the formed ones.
#include <seamless/render/light_planes.h>

#include <catch2/catch.hpp>

#include "test_util.h"

#include <random>
#include <thread>
#include <vector>

using namespace seamless;

TEST_CASE("Light planes are formed on first use, the same bits from any thread", "[light_planes]") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-3, 3);
    constexpr size_t nl = 2, nf = 300;
    std::vector<Vec3> lights(nl), corners(3 * nf);
    for (Vec3& p : lights) p = {u(rng), u(rng), 10 + u(rng)};
    for (Vec3& p : corners) p = {u(rng), u(rng), u(rng)};
    auto expected = [&](size_t l, size_t f) {
        return apex_triangle(lights[l], corners[3 * f], corners[3 * f + 1], corners[3 * f + 2]);
    };
    LightPlanes planes;
    planes.reset(nl, nf);
    REQUIRE(planes.size() == nl * nf);
    CHECK(planes.formed() == 0);

    // Two threads asking for the same planes in opposite orders.
    auto ask = [&](bool reverse, int* mismatches) {
        ApexTriangle scratch;
        for (size_t k = 0; k < nl * nf; ++k) {
            const size_t i = reverse ? nl * nf - 1 - k : k, l = i / nf, f = i % nf;
            const ApexTriangle& p = planes.get(l, f, lights[l], corners[3 * f], corners[3 * f + 1],
                                               corners[3 * f + 2], scratch);
            *mismatches += !test::same_bytes(p, expected(l, f));
        }
    };
    int m1 = 0, m2 = 0;
    std::thread t1(ask, false, &m1), t2(ask, true, &m2);
    t1.join();
    t2.join();
    CHECK(m1 == 0);
    CHECK(m2 == 0);
    CHECK(planes.formed() == nl * nf);

    // A copy keeps what was formed; a fresh table forms only what it is asked.
    const LightPlanes copy = planes;
    CHECK(copy.formed() == nl * nf);
    LightPlanes fresh;
    fresh.reset(nl, nf);
    ApexTriangle scratch;
    CHECK(
        test::same_bytes(fresh.get(1, 7, lights[1], corners[21], corners[22], corners[23], scratch),
                         expected(1, 7)));
    CHECK(fresh.formed() == 1);
}
