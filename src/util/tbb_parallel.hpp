#pragma once
/// @file tbb_parallel.hpp
/// @brief A util::ParallelFor backed by TBB, for the compiled front ends.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <lucent/util/parallel.hpp>

#if defined(__SANITIZE_THREAD__)
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>
#endif

namespace lucent::util {

#if defined(__SANITIZE_THREAD__)
/// Under ThreadSanitizer (scripts/tsan.sh) the same loop on std::threads: Debian's libtbb is not
/// instrumented, so TSan cannot see its task synchronisation and reports every task's writes as
/// racing the caller's reads (341 reports, all of that kind). A thread's join it sees, so what it
/// reports here is a race in lucent. Blocks are handed out dynamically, as TBB's stealing does.
inline void tbbFor(std::size_t n, const RangeBody& body) {
  const std::size_t threads = std::max(2u, std::thread::hardware_concurrency());
  const std::size_t grain = std::max<std::size_t>(1, n / (threads * 8));
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failureLock;
  std::vector<std::thread> pool;
  for (std::size_t t = 0; t < threads; ++t)
    pool.emplace_back([&] {
      try {
        for (std::size_t b; (b = next.fetch_add(grain)) < n;) body(b, std::min(n, b + grain));
      } catch (...) {
        const std::lock_guard<std::mutex> hold(failureLock);
        if (!failure) failure = std::current_exception();
        next = n;  // the others stop at their next block, as TBB cancels the loop
      }
    });
  for (auto& thread : pool) thread.join();
  if (failure) std::rethrow_exception(failure);
}
#else
inline void tbbFor(std::size_t n, const RangeBody& body) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n),
                    [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
}
#endif

}  // namespace lucent::util
