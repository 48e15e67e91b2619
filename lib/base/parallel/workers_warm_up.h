// SPDX-License-Identifier: MIT
// The workers of parallel_chunks (parallel.h) started on a thread of their
// own while the caller does something else (a CLI reading its model), so
// that their start-up is not paid by the first parallel call. TBB's arena
// and threads took 2.5-3 ms there, once per process, on the AMD EPYC VM:
// teapot --tolerance 0.0006525 --threads 2, the tessellation's scaling phase
// 2.8-2.9 ms against 0.5 ms on one thread (docs/results/tessellation.md,
// i11s). Nothing changes but when the workers start.
#pragma once

#include <thread>

namespace seamless {

class WorkersWarmUp {
  public:
    // Starts `threads` workers (as parallel_chunks counts them) in the
    // background; nothing for one thread.
    explicit WorkersWarmUp(int threads);
    // Waits for the start-up (it ends by itself: nothing is cancelled).
    ~WorkersWarmUp();
    WorkersWarmUp(const WorkersWarmUp&) = delete;
    WorkersWarmUp& operator=(const WorkersWarmUp&) = delete;

  private:
    std::thread starter_;
};

} // namespace seamless
