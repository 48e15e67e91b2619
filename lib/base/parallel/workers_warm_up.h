// SPDX-License-Identifier: MIT
// The workers of parallel_chunks (parallel.h) started on a thread of their
// own while the caller does something else (a CLI reading its model), so
// that their start-up (TBB's arena and threads, once per process:
// docs/results/tessellation.md) is not paid by the first parallel call.
// Nothing changes but when the workers start.
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
