// SPDX-License-Identifier: MIT
// KeyTable (key_table.h) against std::unordered_map: the same values for the
// same 64-bit keys (0 among them, and keys equal in their low bits) through
// several doublings, and null for keys never stored.
#include <seamless/base/key_table.h>

#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <unordered_map>
#include <vector>

using namespace seamless;

TEST_CASE("KeyTable stores and finds as unordered_map does", "[key_table]") {
    KeyTable<double> table;
    std::unordered_map<std::uint64_t, double> reference;
    CHECK(table.find(0) == nullptr);
    std::mt19937_64 rng(11);
    std::vector<std::uint64_t> keys = {0, 1, 1ull << 40, 2ull << 40, ~0ull};
    for (int i = 0; i < 5000; ++i) keys.push_back(i % 3 == 0 ? rng() << 20 : rng());
    for (size_t i = 0; i < keys.size(); ++i) {
        const double v = static_cast<double>(i);
        table[keys[i]] = v;
        reference[keys[i]] = v;
        if (i % 7 == 0) table[keys[i / 2]] += 1, reference[keys[i / 2]] += 1;
    }
    CHECK(table.size() == reference.size());
    for (const auto& [k, v] : reference) {
        const double* found = table.find(k);
        REQUIRE(found != nullptr);
        CHECK(*found == v);
    }
    for (int i = 0; i < 1000; ++i) {
        const std::uint64_t k = rng();
        CHECK((table.find(k) == nullptr) == (reference.count(k) == 0));
    }
}

TEST_CASE("KeyTable::reserve keeps every key and value, before and between insertions",
          "[key_table]") {
    KeyTable<int> table;
    table.reserve(1000);
    std::unordered_map<std::uint64_t, int> reference;
    std::mt19937_64 rng(5);
    for (int round = 0; round < 3; ++round) {
        for (int i = 0; i < 700; ++i) {
            const std::uint64_t k = rng() << (round * 8);
            table[k] = i + round;
            reference[k] = i + round;
        }
        // Room for more than is stored (a rehash), and for less (nothing).
        table.reserve(table.size() + 5000);
        table.reserve(1);
        CHECK(table.size() == reference.size());
        for (const auto& [k, v] : reference) {
            const int* found = table.find(k);
            REQUIRE(found != nullptr);
            CHECK(*found == v);
        }
    }
}
