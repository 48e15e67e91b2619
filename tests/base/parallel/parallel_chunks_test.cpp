// SPDX-License-Identifier: MIT
// parallel_chunks (lib/base/parallel/parallel.h): every item once, for any thread
// count, with the arenas kept between calls, nested calls and calls from
// several threads at once.
#include <seamless/base/parallel/parallel.h>

#include <catch2/catch.hpp>

#include <atomic>
#include <thread>
#include <vector>

using namespace seamless;

namespace {

// Each item's visits, counted by parallel_chunks(n, threads).
std::vector<int> visits(int n, int threads) {
    std::vector<std::atomic<int>> seen(n);
    parallel_chunks(n, threads, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) ++seen[i];
    });
    std::vector<int> out(n);
    for (int i = 0; i < n; ++i) out[i] = seen[i];
    return out;
}

} // namespace

TEST_CASE("parallel_chunks visits every item once on any thread count, call after call",
          "[parallel]") {
    for (int threads : {1, 2, 3, 0})
        for (int n : {0, 1, 2, 7, 1000})
            for (int call = 0; call < 3; ++call)
                CHECK(visits(n, threads) == std::vector<int>(n, 1));
}

TEST_CASE("parallel_chunks nested and from several threads at once", "[parallel]") {
    // Nested: each outer item runs an inner parallel_chunks of its own.
    std::vector<std::atomic<int>> inner(64 * 50);
    parallel_chunks(64, 2, [&](int begin, int end) {
        for (int i = begin; i < end; ++i)
            parallel_chunks(50, 2, [&](int b, int e) {
                for (int j = b; j < e; ++j) ++inner[50 * i + j];
            });
    });
    for (auto& v : inner) CHECK(v == 1);
    // Two threads sharing the kept arena of 2 workers.
    std::vector<int> a, b;
    std::thread t1([&] { a = visits(5000, 2); });
    std::thread t2([&] { b = visits(5000, 2); });
    t1.join();
    t2.join();
    CHECK(a == std::vector<int>(5000, 1));
    CHECK(b == std::vector<int>(5000, 1));
}
