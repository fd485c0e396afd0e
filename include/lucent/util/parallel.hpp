#pragma once
/// @file parallel.hpp
/// @brief How core algorithms run loops in parallel without depending on a threading library: they take
/// a ParallelFor, which the caller backs with TBB (src/util/tbb_parallel.hpp), its own job system, or the
/// serial default here.
#include <cstddef>
#include <functional>

namespace lucent::util {

/// Calls body(begin, end) on disjoint ranges that cover [0, n); ranges may run concurrently.
using RangeBody = std::function<void(std::size_t begin, std::size_t end)>;
using ParallelFor = std::function<void(std::size_t n, const RangeBody& body)>;

inline void serialFor(std::size_t n, const RangeBody& body) {
  if (n) body(0, n);
}

/// Reports progress in [0, 1]; called from worker threads, so it must be thread-safe.
using Progress = std::function<void(double fraction)>;

}  // namespace lucent::util
