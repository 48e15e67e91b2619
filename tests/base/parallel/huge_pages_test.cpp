// SPDX-License-Identifier: MIT
// huge_pages.h: allocate_huge gives storage below 512 KB from operator new,
// from 512 KB up 2 MB-aligned, every byte writable either way, and
// huge_array's deleter releases it; reserve_huge changes only where an array
// lives (its elements, their order and what a later resize writes stay the
// same); keep_freed_memory lets freed pages serve later allocations.
#include <seamless/base/parallel/huge_pages.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

using namespace seamless;

TEST_CASE("huge pages: aligned from 512 KB up, every byte writable", "[base][huge_pages]") {
    constexpr std::size_t MB = std::size_t{1} << 20;
    for (const std::size_t bytes : {std::size_t{100}, MB / 2 - 1, MB / 2, MB, 2 * MB + 1, 9 * MB}) {
        auto* p = static_cast<unsigned char*>(allocate_huge(bytes));
        REQUIRE(p != nullptr);
        if (bytes >= MB / 2) CHECK(reinterpret_cast<std::uintptr_t>(p) % (2 * MB) == 0);
        const auto v = static_cast<unsigned char>(bytes % 251);
        std::fill_n(p, bytes, v);
        CHECK(std::count(p, p + bytes, v) == static_cast<std::ptrdiff_t>(bytes));
        release_huge(p, bytes);
    }
    release_huge(nullptr, 9 * MB); // nothing to release
}

TEST_CASE("huge pages: huge_array holds n objects", "[base][huge_pages]") {
    struct Pair {
        double a, b;
    };
    for (const std::size_t n : {std::size_t{0}, std::size_t{10}, std::size_t{200000}}) {
        HugeArray<Pair> arr = huge_array<Pair>(n);
        CHECK((n == 0) == (arr == nullptr));
        for (std::size_t i = 0; i < n; ++i) arr[i] = {double(i), -double(i)};
        if (n > 0) CHECK(arr[n - 1].a == double(n - 1));
    }
}

TEST_CASE("reserve_huge keeps the elements and reserves at least n", "[base][huge_pages][heavy]") {
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
          "[base][huge_pages][native-allocator]") {
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
