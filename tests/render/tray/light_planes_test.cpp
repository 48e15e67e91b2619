// SPDX-License-Identifier: MIT
// Light planes formed on first use (light_planes.h): each is apex_triangle's,
// bit for bit, whichever thread formed it, in whatever order the planes were
// formed (they are stored packed in that order), and whether it was kept or
// not; a copy keeps the formed ones.
#include <seamless/render/tray/light_planes.h>

#include <catch2/catch.hpp>

#include "test_util.h"

#include <algorithm>
#include <random>
#include <thread>
#include <vector>

using namespace seamless;

namespace {

// Random lights above random triangles, and a table of their planes.
struct Planes {
    size_t nl, nf;
    std::vector<Vec3> lights, corners;
    LightPlanes planes;

    Planes(unsigned seed, size_t lights_n, size_t triangles)
        : nl(lights_n), nf(triangles), lights(nl), corners(3 * nf) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(-3, 3);
        for (Vec3& p : lights) p = {u(rng), u(rng), 10 + u(rng)};
        for (Vec3& p : corners) p = {u(rng), u(rng), u(rng)};
        planes.reset(nl, nf);
    }
    ApexTriangle expected(size_t l, size_t f) const {
        return apex_triangle(lights[l], corners[3 * f], corners[3 * f + 1], corners[3 * f + 2]);
    }
    // Entry i = l nf + f of `table` matches apex_triangle bit for bit.
    bool matches(const LightPlanes& table, size_t i) const {
        const size_t l = i / nf, f = i % nf;
        ApexTriangle scratch;
        const ApexTriangle& p = table.get(l, f, lights[l], corners[3 * f], corners[3 * f + 1],
                                          corners[3 * f + 2], scratch);
        return test::same_bytes(p, expected(l, f));
    }
};

} // namespace

TEST_CASE("Light planes are formed on first use, the same bits from any thread", "[light_planes]") {
    Planes t(5, 2, 300);
    const size_t n = t.nl * t.nf;
    REQUIRE(t.planes.size() == n);
    CHECK(t.planes.formed() == 0);

    // Two threads asking for the same planes in opposite orders.
    auto ask = [&](bool reverse, int* mismatches) {
        for (size_t k = 0; k < n; ++k) *mismatches += !t.matches(t.planes, reverse ? n - 1 - k : k);
    };
    int m1 = 0, m2 = 0;
    std::thread t1(ask, false, &m1), t2(ask, true, &m2);
    t1.join();
    t2.join();
    CHECK(m1 == 0);
    CHECK(m2 == 0);
    CHECK(t.planes.formed() == n);

    // A copy keeps what was formed, the same bits; a fresh table forms only what it is asked.
    const LightPlanes copy = t.planes;
    CHECK(copy.formed() == n);
    int copied_mismatches = 0;
    for (size_t i = 0; i < n; ++i) copied_mismatches += !t.matches(copy, i);
    CHECK(copied_mismatches == 0);
    CHECK(copy.formed() == n);
    LightPlanes fresh;
    fresh.reset(t.nl, t.nf);
    CHECK(t.matches(fresh, 1 * t.nf + 7));
    CHECK(fresh.formed() == 1);
}

TEST_CASE("Light planes formed in any order are read back as formed", "[light_planes]") {
    Planes t(11, 3, 200);
    // A scattered quarter of the entries, each asked twice (formed, then kept).
    std::vector<size_t> order(t.nl * t.nf);
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), std::mt19937(3));
    order.resize(order.size() / 4);
    int mismatches = 0;
    for (int pass = 0; pass < 2; ++pass)
        for (size_t i : order) mismatches += !t.matches(t.planes, i);
    CHECK(mismatches == 0);
    CHECK(t.planes.formed() == order.size());
}
