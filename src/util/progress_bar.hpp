#pragma once
/// @file progress_bar.hpp
/// @brief A thread-safe progress bar on stderr for long CLI work. When stderr is not a terminal (a
/// log, a pipe) it writes a plain line every kLogInterval instead, so a user tailing a log sees
/// that work goes on, and a final line.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace lucent::util {

class ProgressBar {
 public:
  explicit ProgressBar(std::string label, bool enabled = true)
      : mLabel(std::move(label)),
        mEnabled(enabled),
        mTty(isatty(STDERR_FILENO)),
        mStart(Clock::now()) {}
  ~ProgressBar() { finish(); }

  /// Seconds between two progress lines in a log.
  static constexpr int kLogInterval = 5;

  /// Thread-safe; redraws at most ten times a second on a terminal, a line every kLogInterval
  /// seconds elsewhere.
  void update(double fraction) {
    if (!mEnabled) return;
    const auto now = Clock::now();
    const auto interval =
        mTty ? std::chrono::milliseconds(100) : std::chrono::seconds(kLogInterval);
    std::unique_lock lock(mMutex, std::try_to_lock);
    if (!lock.owns_lock() || now - (mTty ? mLastDraw : std::max(mLastDraw, mStart)) < interval)
      return;
    mLastDraw = now;
    if (mTty) {
      draw(fraction, now);
    } else {
      const double elapsed = std::chrono::duration<double>(now - mStart).count();
      if (fraction > kEtaFrom)
        std::fprintf(stderr, "%s: %d %% after %.0f s, about %.0f s left\n", mLabel.c_str(),
                     int(fraction * 100), elapsed, secondsLeft(elapsed, fraction));
      else
        std::fprintf(stderr, "%s: %d %% after %.0f s\n", mLabel.c_str(), int(fraction * 100),
                     elapsed);
      std::fflush(stderr);
    }
  }

  void finish() {
    if (!mEnabled || mFinished.exchange(true)) return;
    const double s = std::chrono::duration<double>(Clock::now() - mStart).count();
    std::fprintf(stderr, "%s%-24s done in %.2f s\n", mTty ? "\r" : "", mLabel.c_str(), s);
  }

 private:
  using Clock = std::chrono::steady_clock;
  /// What the rest will cost at the rate so far, once past this fraction.
  static constexpr double kEtaFrom = 0.01;
  static double secondsLeft(double elapsed, double fraction) {
    return elapsed * (1 - fraction) / fraction;
  }
  void draw(double fraction, Clock::time_point now) {
    constexpr int kWidth = 30;
    const int filled = int(fraction * kWidth + 0.5);
    const double elapsed = std::chrono::duration<double>(now - mStart).count();
    const double eta = fraction > kEtaFrom ? secondsLeft(elapsed, fraction) : 0;
    std::fprintf(stderr, "\r%-24s [%s%s] %3d%%  %.1f s left ", mLabel.c_str(),
                 std::string(filled, '#').c_str(), std::string(kWidth - filled, '.').c_str(),
                 int(fraction * 100), eta);
    std::fflush(stderr);
  }
  std::string mLabel;
  bool mEnabled, mTty;
  Clock::time_point mStart, mLastDraw{};
  std::mutex mMutex;
  std::atomic<bool> mFinished{false};
};

}  // namespace lucent::util
