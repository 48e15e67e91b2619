// SPDX-License-Identifier: MIT
// The renderers' one parallel loop: independent work items (rows, screen
// parts) run sequentially when threads == 1, otherwise with TBB in an arena of
// `threads` workers (0: every core). Each item writes only its own pixels and
// statistics, so the result is the same either way.
#pragma once

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace seamless {

template <class Work> void for_each_item(int n, int threads, Work&& work) {
    if (threads == 1) {
        for (int i = 0; i < n; ++i) work(i);
        return;
    }
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    arena.execute([&] { tbb::parallel_for(0, n, [&](int i) { work(i); }); });
}

} // namespace seamless
