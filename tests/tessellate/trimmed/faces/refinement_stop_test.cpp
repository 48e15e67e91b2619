// SPDX-License-Identifier: MIT
// When a face's refinement stops beside sides it does not mend
// (refinement_stop.h): a converging face goes on, one whose failures level
// off past a few dozen triangles per boundary point stops within a few
// rounds, a small face is left to mend its encroachments, and a face grown
// far past what converged faces have stops and counts as crowded.
#include <seamless/tessellate/trimmed/faces/refinement_stop.h>

#include <catch2/catch.hpp>

#include <algorithm>

using namespace seamless;

namespace {

constexpr int kBoundary = 100;

// The round at which `stop` is first due, with the triangles and failures
// of each round from the given functions; -1 when never within `rounds`.
template <class Triangles, class Failing>
int first_due(RefinementStop& stop, int rounds, Triangles triangles, Failing failing) {
    for (int r = 0; r < rounds; ++r)
        if (stop.due(r, failing(r), triangles(r))) return r;
    return -1;
}

} // namespace

TEST_CASE("refinement stop: a face whose failures keep falling goes on", "[brep]") {
    RefinementStop stop(kBoundary);
    // Up to 40 triangles per boundary point, failures falling every round.
    const int due = first_due(
        stop, 40, [](int r) { return static_cast<size_t>(kBoundary * (1 + r)); },
        [](int r) { return static_cast<size_t>(1000 - 20 * r); });
    CHECK(due == -1);
    CHECK_FALSE(stop.crowded(40 * kBoundary));
}

TEST_CASE("refinement stop: failures levelled off on a grown face stop it", "[brep]") {
    RefinementStop stop(kBoundary);
    // 40 triangles per boundary point, failures falling until round 10,
    // then level.
    const int due = first_due(
        stop, 40, [](int) { return static_cast<size_t>(40 * kBoundary); },
        [](int r) { return static_cast<size_t>(500 - 20 * std::min(r, 10)); });
    CHECK(due > 10);
    CHECK(due <= 20);
}

TEST_CASE("refinement stop: a small face's levelled failures do not stop it", "[brep]") {
    RefinementStop stop(kBoundary);
    // Failures level from the start, but at a few triangles per boundary
    // point: refinement mends most encroachments on such faces.
    const int due = first_due(
        stop, 40, [](int) { return static_cast<size_t>(8 * kBoundary); },
        [](int) { return size_t{300}; });
    CHECK(due == -1);
}

TEST_CASE("refinement stop: a face grown far past converged ones stops, crowded", "[brep]") {
    RefinementStop stop(kBoundary);
    // Failures still falling, but a thousand triangles per boundary point.
    CHECK(stop.due(0, 5000, 1000 * kBoundary));
    CHECK(stop.crowded(1000 * kBoundary));
}
