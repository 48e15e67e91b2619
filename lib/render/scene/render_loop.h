// SPDX-License-Identifier: MIT
// The renderers' one parallel loop: independent work items (rows, screen
// parts) through base/parallel.h (sequential when threads == 1, TBB otherwise;
// 0: every core). Each item writes only its own pixels and statistics, so the
// result is the same either way.
#pragma once

#include <seamless/base/parallel/parallel.h>
#include <seamless/render/scene/render_options.h>
#include <seamless/render/scene/render_stats.h>

#include <algorithm>
#include <atomic>
#include <vector>

namespace seamless {

template <class Work> void for_each_item(int n, int threads, Work&& work) {
    parallel_chunks(n, threads, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) work(i);
    });
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
