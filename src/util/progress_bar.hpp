#pragma once
/// @file progress_bar.hpp
/// @brief A thread-safe progress bar on stderr for long CLI work; quiet when stderr is not a terminal
/// except for a final line, so logs stay readable.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace lucent::util {

class ProgressBar {
 public:
  explicit ProgressBar(std::string label, bool enabled = true)
      : mLabel(std::move(label)), mEnabled(enabled), mTty(isatty(STDERR_FILENO)), mStart(Clock::now()) {}
  ~ProgressBar() { finish(); }

  /// Thread-safe; redraws at most ten times a second.
  void update(double fraction) {
    if (!mEnabled || !mTty) return;
    const auto now = Clock::now();
    std::unique_lock lock(mMutex, std::try_to_lock);
    if (!lock.owns_lock() || now - mLastDraw < std::chrono::milliseconds(100)) return;
    mLastDraw = now;
    draw(fraction, now);
  }

  void finish() {
    if (!mEnabled || mFinished.exchange(true)) return;
    const double s = std::chrono::duration<double>(Clock::now() - mStart).count();
    std::fprintf(stderr, "%s%-24s done in %.2f s\n", mTty ? "\r" : "", mLabel.c_str(), s);
  }

 private:
  using Clock = std::chrono::steady_clock;
  void draw(double fraction, Clock::time_point now) {
    constexpr int kWidth = 30;
    const int filled = int(fraction * kWidth + 0.5);
    const double elapsed = std::chrono::duration<double>(now - mStart).count();
    const double eta = fraction > 0.01 ? elapsed * (1 - fraction) / fraction : 0;
    std::fprintf(stderr, "\r%-24s [%s%s] %3d%%  %.1f s left ", mLabel.c_str(), std::string(filled, '#').c_str(),
                 std::string(kWidth - filled, '.').c_str(), int(fraction * 100), eta);
    std::fflush(stderr);
  }
  std::string mLabel;
  bool mEnabled, mTty;
  Clock::time_point mStart, mLastDraw{};
  std::mutex mMutex;
  std::atomic<bool> mFinished{false};
};

}  // namespace lucent::util
