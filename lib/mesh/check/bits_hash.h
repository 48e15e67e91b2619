// SPDX-License-Identifier: MIT
// Hash of N 64-bit words (the bit patterns of coordinates), for finding
// bit-identical positions, edges and triangles in the mesh checks.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace seamless {

struct BitsHash {
    template <std::size_t N> std::size_t operator()(const std::array<std::uint64_t, N>& k) const {
        std::uint64_t h = 1469598103934665603ull;
        for (std::uint64_t x : k) h = (h ^ x) * 1099511628211ull ^ (x >> 29);
        return static_cast<std::size_t>(h);
    }
};

} // namespace seamless
