// SPDX-License-Identifier: MIT
// Numbering as first met over flat arrays (first_met.h).
#include <seamless/base/first_met.h>
#include <seamless/tessellate/seams/shared_edges.h>

#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <unordered_map>
#include <vector>

using namespace seamless;

TEST_CASE("FirstMet keeps the first value of each key, as an unordered_map's try_emplace",
          "[first_met]") {
    std::mt19937_64 rng(7);
    FirstMet<std::uint64_t, MixHash> met;
    for (int round = 0; round < 3; ++round) {
        // Dyadic keys (many trailing zero bits) as the subdivision grid gives.
        const int n = 1000 << round;
        std::vector<std::uint64_t> keys(n);
        for (auto& k : keys) k = (rng() % 97) << (32 + round) | ((rng() % 61) << 20);
        met.reset(keys.size());
        std::unordered_map<std::uint64_t, int> ref;
        for (int i = 0; i < n; ++i)
            CHECK(met.emplace(keys[i], i) == ref.try_emplace(keys[i], i).first->second);
    }
    // Reset forgets every key.
    met.reset(1);
    CHECK(met.emplace(5, 1) == 1);
    CHECK(met.emplace(5, 2) == 1);
    met.reset(1);
    CHECK(met.emplace(5, 3) == 3);
}

TEST_CASE("FirstMet over vertex keys", "[first_met]") {
    FirstMet<VertexKey, VertexKeyHash> met;
    std::vector<VertexKey> keys;
    for (int kind = 0; kind < 3; ++kind)
        for (int id = 0; id < 5; ++id)
            for (int a = 0; a < 4; ++a) keys.push_back({kind, id, a << 28, kind == 2 ? a : 0});
    met.reset(2 * keys.size());
    for (size_t i = 0; i < keys.size(); ++i) CHECK(met.emplace(keys[i], int(i)) == int(i));
    for (size_t i = 0; i < keys.size(); ++i) CHECK(met.emplace(keys[i], 1000) == int(i));
}
