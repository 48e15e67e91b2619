// SPDX-License-Identifier: MIT
// Fresh storage backed by the workers before it is filled (touched_storage.h):
// only the storage changes, never the contents.
#include <seamless/base/parallel/touched_storage.h>

#include <catch2/catch.hpp>

#include <cstddef>
#include <numeric>
#include <vector>

using namespace seamless;

TEST_CASE("reserve_touched keeps the elements and makes room, below and above 2 MB",
          "[touched_storage]") {
    // 40 KB (one piece), 1 MB (pieces shared among the workers), 12 MB (2 MB pages).
    for (const std::size_t n : {std::size_t{10'000}, std::size_t{250'000}, std::size_t{3'000'000}})
        for (const int threads : {1, 2, 0}) {
            std::vector<int> v(1000);
            std::iota(v.begin(), v.end(), 7);
            reserve_touched(v, n, threads);
            REQUIRE(v.size() == 1000);
            CHECK(v.capacity() >= n);
            for (int i = 0; i < 1000; ++i) CHECK(v[i] == i + 7);
            // Room already there: nothing moves.
            const int* data = v.data();
            reserve_touched(v, n / 2, threads);
            CHECK(v.data() == data);
            v.resize(n, -1);
            CHECK(v.back() == -1);
            CHECK(v[999] == 1006);
        }
}

TEST_CASE("assign_touched is assign", "[touched_storage]") {
    for (const int threads : {1, 2}) {
        std::vector<double> v{1, 2, 3};
        assign_touched(v, 100'000, 0.5, threads);
        REQUIRE(v.size() == 100'000);
        CHECK(v.front() == 0.5);
        CHECK(v.back() == 0.5);
        assign_touched(v, 2, 1.5, threads);
        CHECK(v == std::vector<double>{1.5, 1.5});
    }
}
