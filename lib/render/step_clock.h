// SPDX-License-Identifier: MIT
// Thread CPU seconds per INTRACY step for --stats: on a shared machine a
// step's own cost, not the time other jobs held the core.
#pragma once

#include <ctime>

namespace seamless {

inline double thread_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Adds the thread's CPU seconds from construction to destruction to `acc`.
class StepClock {
  public:
    explicit StepClock(double& acc) : acc_(acc), t0_(thread_seconds()) {}
    StepClock(const StepClock&) = delete;
    StepClock& operator=(const StepClock&) = delete;
    ~StepClock() { acc_ += thread_seconds() - t0_; }

  private:
    double& acc_;
    double t0_;
};

} // namespace seamless
