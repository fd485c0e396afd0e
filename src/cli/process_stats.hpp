#pragma once
/// @file process_stats.hpp
/// @brief Peak resident memory of this process (getrusage), in MiB.
#include <sys/resource.h>

namespace lucent::cli {

inline double peakMemoryMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

}  // namespace lucent::cli
