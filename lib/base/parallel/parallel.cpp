// SPDX-License-Identifier: MIT
#include <seamless/base/parallel/parallel.h>

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <map>
#include <memory>
#include <mutex>

namespace seamless {
namespace {

// One arena per worker count, made on first use and kept: making one costs
// several times more than entering a kept one, and a tessellation makes
// dozens of calls (docs/results/tessellation.md). Never destroyed: TBB's own
// state may be gone when statics are.
tbb::task_arena& arena_of(int workers) {
    static std::mutex lock;
    static auto* arenas = new std::map<int, std::unique_ptr<tbb::task_arena>>;
    const std::lock_guard<std::mutex> hold(lock);
    std::unique_ptr<tbb::task_arena>& a = (*arenas)[workers];
    if (!a) a = std::make_unique<tbb::task_arena>(workers);
    return *a;
}

} // namespace

void parallel_chunks(int n, int threads, const std::function<void(int, int)>& chunk) {
    if (n <= 0) return;
    if (threads == 1 || n == 1) {
        chunk(0, n);
        return;
    }
    // More workers than cores only draw TBB's warning; the result is the same.
    const int cores = tbb::info::default_concurrency();
    arena_of(threads > 0 ? std::min(threads, cores) : cores).execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, n),
                          [&](const tbb::blocked_range<int>& r) { chunk(r.begin(), r.end()); });
    });
}

} // namespace seamless
