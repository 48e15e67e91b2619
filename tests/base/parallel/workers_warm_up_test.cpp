// SPDX-License-Identifier: MIT
// WorkersWarmUp (lib/base/parallel/workers_warm_up.h): parallel_chunks visits every
// item once while the workers start in the background, after they started,
// and for every thread count (one thread: nothing started).
#include <seamless/base/parallel/parallel.h>
#include <seamless/base/parallel/workers_warm_up.h>

#include <catch2/catch.hpp>

#include <atomic>
#include <vector>

using namespace seamless;

namespace {

bool each_once(int n, int threads) {
    std::vector<std::atomic<int>> seen(n);
    parallel_chunks(n, threads, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) ++seen[i];
    });
    for (const std::atomic<int>& s : seen)
        if (s != 1) return false;
    return true;
}

} // namespace

TEST_CASE("WorkersWarmUp: parallel work during and after the workers' start", "[parallel]") {
    for (int threads : {1, 2, 3, 0}) {
        {
            const WorkersWarmUp warm_up(threads);
            CHECK(each_once(1000, threads)); // while it may still run
        }
        CHECK(each_once(1000, threads)); // after it ended
    }
}
