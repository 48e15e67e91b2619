// SPDX-License-Identifier: MIT
#include <seamless/base/parallel/parallel.h>
#include <seamless/base/parallel/workers_warm_up.h>

namespace seamless {

WorkersWarmUp::WorkersWarmUp(int threads) {
    if (threads == 1) return;
    // One empty item per worker: each worker thread joins the arena once.
    const int items = threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
    starter_ = std::thread([threads, items] { parallel_chunks(items, threads, [](int, int) {}); });
}

WorkersWarmUp::~WorkersWarmUp() {
    if (starter_.joinable()) starter_.join();
}

} // namespace seamless
