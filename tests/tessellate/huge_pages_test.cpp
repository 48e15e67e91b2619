// SPDX-License-Identifier: MIT
// reserve_huge (huge_pages.h) changes only where an array lives: its
// elements, their order and what a later resize writes stay the same; and
// keep_freed_memory lets freed pages serve later allocations.
#include <seamless/tessellate/huge_pages.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

using namespace seamless;

TEST_CASE("reserve_huge keeps the elements and reserves at least n", "[tessellate][huge_pages]") {
    // threads 2: the new storage is first touched by two workers (touch_pages).
    for (int threads : {1, 2})
        for (std::size_t size : {0u, 1u, 1000u, 300000u})
            for (std::size_t n : {0u, 10u, 700000u, 2000000u}) {
                std::vector<std::uint64_t> v(size);
                for (std::size_t i = 0; i < size; ++i) v[i] = i * 0x9E3779B97F4A7C15ull;
                const std::uint64_t* before = v.data();
                const std::size_t capacity = v.capacity();
                reserve_huge(v, n, threads);
                REQUIRE(v.size() == size);
                REQUIRE(v.capacity() >= n);
                if (n <= capacity) CHECK(v.data() == before); // nothing to do: no new storage
                for (std::size_t i = 0; i < size; ++i) REQUIRE(v[i] == i * 0x9E3779B97F4A7C15ull);
                v.resize(std::max(n, size), 7);
                for (std::size_t i = size; i < v.size(); ++i) REQUIRE(v[i] == 7);
            }
}

#if defined(__GLIBC__)
#include <sys/resource.h>

namespace {
long minor_faults() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_minflt;
}
} // namespace

TEST_CASE("keep_freed_memory: a freed 16 MB block's pages serve the next one",
          "[tessellate][huge_pages]") {
    keep_freed_memory();
    constexpr std::size_t n = std::size_t{16} << 20; // 4,096 pages of 4 KB
    auto fill = [] {
        std::vector<unsigned char> v(n, 1);
        return static_cast<long>(v[n / 2]);
    };
    fill(); // touched once, then freed
    const long before = minor_faults();
    CHECK(fill() == 1);
    // Without keep_freed_memory the block is mmapped and unmapped again:
    // about 4,096 fresh faults (or 8 with 2 MB pages); kept, almost none.
    CHECK(minor_faults() - before < 64);
}
#endif
