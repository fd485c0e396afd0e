#pragma once
/// @file tbb_parallel.hpp
/// @brief A util::ParallelFor backed by TBB, for the compiled front ends.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <lucent/util/parallel.hpp>

namespace lucent::util {

inline void tbbFor(std::size_t n, const RangeBody& body) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n),
                    [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
}

}  // namespace lucent::util
