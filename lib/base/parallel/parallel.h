// SPDX-License-Identifier: MIT
// Independent work items [0, n) on `threads` workers (0: every core, 1:
// sequentially on the caller's thread). Items write only their own slots, so
// the result is the same for any thread count; chunk(begin, end) may keep
// scratch storage for its items. TBB stays inside parallel.cpp.
#pragma once

#include <functional>

namespace seamless {

void parallel_chunks(int n, int threads, const std::function<void(int begin, int end)>& chunk);

} // namespace seamless
