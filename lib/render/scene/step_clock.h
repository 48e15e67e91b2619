// SPDX-License-Identifier: MIT
// Thread CPU seconds per INTRACY step for --stats: on a shared machine a
// step's own cost, not the time other jobs held the core.
//
// The thread CPU clock is a system call (no vDSO), and INTRACY's steps are
// short: reading it around every step cost a noticeable share of a render. So a
// step reads the monotonic clock (vDSO, tens of ns), and a part of the screen
// reads the thread CPU clock once at each end (PartCpuScale): the steps' wall
// seconds are scaled by the part's CPU / wall ratio. Where other jobs preempt
// the thread uniformly this is each step's CPU time.
#pragma once

#include <chrono>
#include <ctime>

namespace seamless {

inline double thread_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
inline double wall_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// Adds the wall seconds from construction to destruction to `acc`.
class StepClock {
  public:
    explicit StepClock(double& acc) : acc_(acc), t0_(wall_seconds()) {}
    StepClock(const StepClock&) = delete;
    StepClock& operator=(const StepClock&) = delete;
    ~StepClock() { acc_ += wall_seconds() - t0_; }

  private:
    double& acc_;
    double t0_;
};

// The ratio of the thread's CPU seconds to wall seconds over a part's run:
// multiplies the StepClock sums of that part into CPU seconds.
class PartCpuScale {
  public:
    PartCpuScale() : cpu0_(thread_seconds()), wall0_(wall_seconds()) {}
    double factor() const {
        const double wall = wall_seconds() - wall0_, cpu = thread_seconds() - cpu0_;
        return wall > 0 ? cpu / wall : 1.0;
    }

  private:
    double cpu0_, wall0_;
};

} // namespace seamless
