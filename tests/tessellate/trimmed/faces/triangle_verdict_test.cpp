// SPDX-License-Identifier: MIT
// Accepted triangles (triangle_verdict.h): a redo finds a triangle's verdict
// by its corners in any rotation, with the normals in its own corner order,
// and only with the same sides on the boundary.
#include <seamless/tessellate/trimmed/faces/triangle_verdict.h>

#include <catch2/catch.hpp>

#include <random>

using namespace seamless;

TEST_CASE("accepted triangles: found in any rotation, only with the same sides", "[brep]") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> x(-3, 3);
    AcceptedTriangles memo;
    struct Added {
        std::array<Vec3, 3> uv;
        std::array<bool, 3> boundary;
        TriangleVerdict v;
    };
    std::vector<Added> added;
    for (int k = 0; k < 200; ++k) {
        Added a;
        for (int i = 0; i < 3; ++i) {
            a.uv[i] = {x(rng), x(rng), 0};
            a.boundary[i] = (k >> i) & 1;
            a.v.normals[i] = {x(rng), x(rng), x(rng)};
        }
        a.v.deviation = k;
        a.v.drop = k % 7 == 0;
        memo.add(a.uv, a.boundary, a.v);
        added.push_back(a);
    }
    memo.seal();
    REQUIRE(memo.size() == added.size());
    for (const Added& a : added)
        for (int r = 0; r < 3; ++r) {
            // The same triangle with its corners rotated by r.
            std::array<Vec3, 3> uv;
            std::array<bool, 3> boundary;
            for (int i = 0; i < 3; ++i)
                uv[i] = a.uv[(i + r) % 3], boundary[i] = a.boundary[(i + r) % 3];
            TriangleVerdict v;
            REQUIRE(memo.find(uv, boundary, v));
            CHECK(v.deviation == a.v.deviation);
            CHECK(v.drop == a.v.drop);
            CHECK_FALSE(v.split);
            for (int i = 0; i < 3; ++i) CHECK(v.normals[i] == a.v.normals[(i + r) % 3]);
            // A side that became a boundary side (or stopped being one), or
            // a corner moved by a rounding: not the same triangle.
            boundary[r] = !boundary[r];
            CHECK_FALSE(memo.find(uv, boundary, v));
            boundary[r] = !boundary[r];
            uv[r].y = std::nextafter(uv[r].y, 10.0);
            CHECK_FALSE(memo.find(uv, boundary, v));
        }
}
