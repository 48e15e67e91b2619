// SPDX-License-Identifier: MIT
// A progress bar on stderr, drawn only when stderr is a terminal. Thread-safe:
// the renderers call it from worker threads.
#pragma once

#include <cstdio>
#include <mutex>
#include <string>
#include <unistd.h>

namespace seamless::cli {

class ProgressBar {
  public:
    explicit ProgressBar(std::string label) : label_(std::move(label)), enabled_(::isatty(2)) {}
    ~ProgressBar() { finish(); }

    void update(double fraction) {
        if (!enabled_) return;
        std::lock_guard<std::mutex> lock(mutex_);
        const int percent = static_cast<int>(fraction * 100.0 + 0.5);
        if (percent <= last_) return; // workers may report out of order: never backwards
        last_ = percent;
        const int filled = percent * kWidth / 100;
        std::string bar(static_cast<size_t>(filled), '#');
        bar.resize(kWidth, '.');
        std::fprintf(stderr, "\r%s [%s] %3d%%", label_.c_str(), bar.c_str(), percent);
        std::fflush(stderr);
        drawn_ = true;
    }
    void finish() {
        std::lock_guard<std::mutex> lock(mutex_);
        if (drawn_) std::fprintf(stderr, "\r\033[K");
        drawn_ = false;
    }

  private:
    static constexpr int kWidth = 40;
    std::string label_;
    bool enabled_;
    bool drawn_ = false;
    int last_ = -1;
    std::mutex mutex_;
};

} // namespace seamless::cli
