// SPDX-License-Identifier: MIT
// Numbering as first met (the edge registry's lines, the vertices) without a
// heap node per key: open addressing over two flat arrays sized to the data
// (at most half full), linear probing. The storage is kept across reset().
#pragma once

#include <seamless/base/check.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace seamless {

template <class Key, class Hash> class FirstMet {
  public:
    // Room for up to n keys; forgets every key.
    void reset(std::size_t n) {
        std::size_t size = 16;
        while (size < 2 * n) size *= 2;
        mask_ = size - 1;
        keys_.resize(size);
        values_.assign(size, -1);
        used_ = 0;
    }
    // The value stored with `key`; stores `value` (>= 0) when the key is new.
    int emplace(const Key& key, int value) {
        std::size_t h = Hash{}(key)&mask_;
        while (values_[h] >= 0 && !(keys_[h] == key)) h = (h + 1) & mask_;
        if (values_[h] < 0) {
            // More keys than reset() made room for would fill the table and
            // the probe above would never end: the caller's count is wrong.
            SEAMLESS_CHECK(used_ < mask_ / 2 + 1, "more keys than reset() made room for");
            keys_[h] = key, values_[h] = value;
            ++used_;
        }
        return values_[h];
    }

  private:
    std::vector<Key> keys_;
    std::vector<int> values_;
    std::size_t mask_ = 0;
    std::size_t used_ = 0;
};

// A 64-bit key's hash for FirstMet (Fibonacci hashing, high bits folded in).
struct MixHash {
    std::size_t operator()(std::uint64_t k) const {
        const std::uint64_t h = k * 0x9E3779B97F4A7C15ull;
        return static_cast<std::size_t>(h ^ (h >> 32));
    }
};

} // namespace seamless
