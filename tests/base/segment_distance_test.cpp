// SPDX-License-Identifier: MIT
// segment_distance.h: the distance to a segment's interior, to its ends past
// them, and to a segment collapsed to a point.
#include <seamless/base/segment_distance.h>

#include <catch2/catch.hpp>

using namespace seamless;

TEST_CASE("point_segment_distance handles interior, end and degenerate segments", "[planarity]") {
    CHECK(point_segment_distance({0.5, 1, 0}, {0, 0, 0}, {1, 0, 0}) == Approx(1));
    CHECK(point_segment_distance({2, 0, 0}, {0, 0, 0}, {1, 0, 0}) == Approx(1));
    CHECK(point_segment_distance({0, 3, 4}, {0, 0, 0}, {0, 0, 0}) == Approx(5));
}
