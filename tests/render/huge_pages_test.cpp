// SPDX-License-Identifier: MIT
// huge_pages.h: storage below 512 KB from operator new, from 512 KB up 2 MB-aligned;
// every byte writable either way, and huge_array's deleter releases it.
#include <seamless/render/huge_pages.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>

using namespace seamless;

TEST_CASE("huge pages: aligned from 512 KB up, every byte writable", "[huge_pages]") {
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

TEST_CASE("huge pages: huge_array holds n objects", "[huge_pages]") {
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
