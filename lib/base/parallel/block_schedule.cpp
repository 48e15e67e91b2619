// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/base/parallel/block_schedule.h>
#include <seamless/base/parallel/parallel.h>

#include <algorithm>
#include <atomic>

namespace seamless {

void pull_blocks(int n, int grain, int threads, const std::vector<int>* order,
                 const std::function<void(int begin, int end)>& chunk) {
    SEAMLESS_CHECK(!order || grain == 1, "an order of blocks with a grain above 1");
    const int blocks = (n + grain - 1) / grain;
    std::atomic<int> next{0};
    parallel_chunks(blocks, threads, [&](int, int) {
        for (int b; (b = next.fetch_add(1, std::memory_order_relaxed)) < blocks;) {
            if (order)
                chunk((*order)[b], (*order)[b] + 1);
            else
                chunk(b * grain, std::min(n, (b + 1) * grain));
        }
    });
}

} // namespace seamless
