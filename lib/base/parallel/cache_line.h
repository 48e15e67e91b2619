// SPDX-License-Identifier: MIT
// Items that workers fill at the same time (one per block or patch taken by
// pull_blocks, block_schedule.h), each on a cache line of its own. A vector's
// header is written as it grows (its end), so two such vectors side by side
// in an array have each worker's writes evict the line the other worker is
// using (false sharing): the verdict tables and parts of neighbouring
// patches, which the largest-first order hands the two workers at once
// (docs/results/tessellation.md).
// Only the storage's layout changes: the values and the output are the same.
#pragma once

#include <cstddef>

namespace seamless {

// A line on the x86-64 and ARM processors this runs on (not
// std::hardware_destructive_interference_size, whose value varies with
// compiler flags and draws GCC's -Winterference-size in headers).
inline constexpr std::size_t kCacheLine = 64;

// One item on its own cache line(s), for arrays of per-worker-item storage.
template <class T> struct alignas(kCacheLine) OwnLine { T value; };

} // namespace seamless
