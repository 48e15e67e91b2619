// SPDX-License-Identifier: MIT
#include <seamless/base/parallel.h>

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>

namespace seamless {

void parallel_chunks(int n, int threads, const std::function<void(int, int)>& chunk) {
    if (n <= 0) return;
    if (threads == 1 || n == 1) {
        chunk(0, n);
        return;
    }
    // More workers than cores only draw TBB's warning; the result is the same.
    const int cores = tbb::info::default_concurrency();
    tbb::task_arena arena(threads > 0 ? std::min(threads, cores) : cores);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, n),
                          [&](const tbb::blocked_range<int>& r) { chunk(r.begin(), r.end()); });
    });
}

} // namespace seamless
