// SPDX-License-Identifier: MIT
// Dynamic scheduling on parallel_chunks (parallel.h): whichever worker is
// free takes the next block of `grain` items, so the workers finish within one
// block of each other (a fixed chunk of whole patches left one thread idle
// while the other finished it). With `order` (grain 1) the items are taken in
// that order: largest first, the last blocks are the smallest (longest
// processing time first). Items write only their own slots, so the result is
// the same for any thread count and any order.
#pragma once

#include <functional>
#include <vector>

namespace seamless {

// Subpatches per block: small against the tens of thousands of a fine
// tessellation, large against the cost of taking a block.
inline constexpr int kSubpatchBlock = 32;

void pull_blocks(int n, int grain, int threads, const std::vector<int>* order,
                 const std::function<void(int begin, int end)>& chunk);

} // namespace seamless
