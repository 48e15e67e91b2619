// SPDX-License-Identifier: MIT
// TessellationOptions::progress within one pass of a tessellation: the
// phases of a pass by their share of its time, the subdivision and the
// bounds also within themselves (by patch cost and by block of subpatches).
#pragma once

#include <functional>

namespace seamless {

class PassProgress {
  public:
    // Where each phase of a pass ends, as a fraction of the pass: the phase
    // seconds of the teapot at 1e-4 d_max on one thread (subdivision 33 %,
    // boundaries 6 %, rings 13 %, numbering 2 %, bounds 36 %, normals, fans
    // and orientation 10 %).
    static constexpr double kSubdivided = 0.33, kBoundaries = 0.39, kRings = 0.52, kNumbered = 0.54,
                            kBounded = 0.90, kNormals = 0.92, kFans = 0.96;

    // `report` may be empty (nothing is reported). The first pass reports 0
    // to 0.9 of the whole; each later one, which redoes only what changed,
    // half of what the one before left.
    PassProgress(const std::function<void(double)>& report, int pass) : report_(&report) {
        double left = 0.1;
        for (int k = 1; k < pass; ++k) left /= 2;
        start_ = pass == 0 ? 0 : 1 - left;
        span_ = pass == 0 ? 0.9 : left / 2;
    }

    // The pass is `fraction` done. From any thread.
    void at(double fraction) const {
        if (*report_) (*report_)(start_ + span_ * fraction);
    }
    // `done` of `total` of the phase that runs from `from` to `to` of the pass.
    void within(double from, double to, double done, double total) const {
        if (*report_ && total > 0) at(from + (to - from) * (done < total ? done / total : 1.0));
    }
    explicit operator bool() const { return static_cast<bool>(*report_); }

  private:
    const std::function<void(double)>* report_; // not owned
    double start_ = 0, span_ = 0;
};

} // namespace seamless
