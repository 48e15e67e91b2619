// SPDX-License-Identifier: MIT
// The renderers' one parallel loop: independent work items (rows, screen
// parts) run sequentially when threads == 1, otherwise with TBB in an arena of
// `threads` workers (0: every core). Each item writes only its own pixels and
// statistics, so the result is the same either way.
#pragma once

#include <seamless/render/render.h>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <vector>

namespace seamless {

template <class Work> void for_each_item(int n, int threads, Work&& work) {
    if (threads == 1) {
        for (int i = 0; i < n; ++i) work(i);
        return;
    }
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    arena.execute([&] { tbb::parallel_for(0, n, [&](int i) { work(i); }); });
}

// The per-pixel renderers' loop (TRAY, the reference): row(y, stats) for
// every row, rows in parallel as `options.threads` says, progress reported,
// the rows' statistics merged into `st`, every pixel counted as a one-pixel
// sub-screen.
template <class Row>
void render_rows(int width, int height, const RenderOptions& options, RenderStats& st, Row&& row) {
    std::vector<RenderStats> row_stats(height);
    std::atomic<int> done{0};
    for_each_item(height, options.threads, [&](int y) {
        row(y, row_stats[y]);
        const int d = ++done;
        if (options.progress && d % std::max(1, height / 100) == 0)
            options.progress(static_cast<double>(d) / height);
    });
    for (const RenderStats& s : row_stats) st.merge(s);
    st.subscreens_by_size[1] = static_cast<long long>(width) * height;
}

} // namespace seamless
