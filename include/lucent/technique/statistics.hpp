#pragma once
/// @file statistics.hpp
/// @brief What a technique reports about its work, typed so the bench and the planner read it
/// without knowing the technique: per-phase seconds, the samples its accuracy is bought with,
/// bytes, extras.
#include <chrono>
#include <map>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace lucent::technique {

/// Wall time since construction (or restart), in seconds.
class Stopwatch {
 public:
  double seconds() const { return std::chrono::duration<double>(Clock::now() - mStart).count(); }
  void restart() { mStart = Clock::now(); }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point mStart = Clock::now();
};

struct Statistics {
  /// (phase, seconds) in the order run: prepare phases ("atlas", "samples", "graph") and frame
  /// phases
  /// ("irradiance", "sampling", "evaluation", "solve").
  std::vector<std::pair<std::string, double>> prepareSeconds, frameSeconds;
  double samples =
      0;  ///< what the accuracy is bought with (surface samples, importance samples, paths)
  std::string sampleUnit;                 ///< what `samples` counts
  double bytes = 0;                       ///< memory of the prepared structures
  std::map<std::string, double> figures;  ///< technique-specific counts and measures
  std::vector<std::string> warnings;      ///< what a user must see (budget limits, clamped values)

  double totalPrepareSeconds() const { return sum(prepareSeconds); }
  double totalFrameSeconds() const { return sum(frameSeconds); }

  /// Runs `work`, recording its wall time as a prepare or frame phase.
  template <class Work>
  auto timePrepare(const std::string& phase, Work&& work) {
    return timed(prepareSeconds, phase, work);
  }
  template <class Work>
  auto timeFrame(const std::string& phase, Work&& work) {
    return timed(frameSeconds, phase, work);
  }

  /// Every number as one flat map: "<phase>_seconds", "prepare_seconds", "frame_seconds",
  /// "samples", "bytes", and the figures (what the CLI's stats JSON and the bench's table carry).
  std::map<std::string, double> flat() const {
    std::map<std::string, double> out = figures;
    for (const auto& [phase, s] : prepareSeconds) out[phase + "_seconds"] += s;
    for (const auto& [phase, s] : frameSeconds) out[phase + "_seconds"] += s;
    out["prepare_seconds"] = totalPrepareSeconds();
    out["frame_seconds"] = totalFrameSeconds();
    out["samples"] = samples;
    out["bytes"] = bytes;
    return out;
  }

 private:
  static double sum(const std::vector<std::pair<std::string, double>>& v) {
    double s = 0;
    for (const auto& p : v) s += p.second;
    return s;
  }
  template <class Work>
  static auto timed(std::vector<std::pair<std::string, double>>& into, const std::string& phase,
                    Work& work) {
    const Stopwatch clock;
    if constexpr (std::is_void_v<decltype(work())>) {
      work();
      into.emplace_back(phase, clock.seconds());
    } else {
      auto result = work();
      into.emplace_back(phase, clock.seconds());
      return result;
    }
  }
};

}  // namespace lucent::technique
