// SPDX-License-Identifier: MIT
// Wall-clock laps for the phases of a tessellation (PhaseSeconds,
// tessellation.h).
#pragma once

#include <chrono>

namespace seamless {

// Seconds since the previous call (or construction), for PhaseSeconds.
class Lap {
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();

  public:
    double operator()() {
        const auto now = std::chrono::steady_clock::now();
        const double d = std::chrono::duration<double>(now - last_).count();
        last_ = now;
        return d;
    }
};

// Seconds since `start`.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace seamless
