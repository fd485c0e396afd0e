#pragma once
/// @file roofline.hpp
/// @brief What this machine can do, measured inside the benchmark's own process, so that a stage's
/// speed has a yardstick: the peak float FMA rate (independent FMA chains at full vector width,
/// compiled for AVX2 + FMA by LUCENT_VECTOR_CLONES) and the STREAM triad bandwidth a = b + s c
/// (McCalpin 1995) over arrays far larger than the caches. A stage's achieved GFLOP/s over the
/// first, or GB/s over the second, is its fraction of the roofline (Williams, Waterman, Patterson
/// 2009).
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <thread>
#include <vector>

#include <lucent/util/simd.hpp>

namespace lucent::bench {

namespace detail {
/// FMA chains: each lane is a chain acc = acc a + b. 96 lanes are 12 AVX2 registers, more chains
/// than FMA latency (4 cycles) x ports (2) need, and few enough to stay in the 16 registers.
inline constexpr int kFmaLanes = 96;

LUCENT_VECTOR_CLONES inline float fmaChains(long iterations, float seed) {
  float acc[kFmaLanes];
  for (int j = 0; j < kFmaLanes; ++j) acc[j] = seed + 0.001f * float(j);
  const float a = 0.999999f, b = 1e-7f;
  for (long i = 0; i < iterations; ++i) {
#pragma omp simd
    for (int j = 0; j < kFmaLanes; ++j) acc[j] = acc[j] * a + b;
  }
  float sum = 0;
  for (const float v : acc) sum += v;
  return sum;
}

/// Runs `work(thread)` on `threads` threads at once; the wall seconds.
template <class Work>
double wallSeconds(unsigned threads, const Work& work) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t) pool.emplace_back([&work, t] { work(t); });
  for (auto& th : pool) th.join();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace detail

/// Peak float FMA rate of `threads` threads together, GFLOP/s (an FMA is 2 flops per lane); the
/// best of three runs of about `seconds` each.
inline double fmaPeakGflops(unsigned threads, double seconds = 0.25) {
  volatile float sink = 0;
  long iterations = 1 << 16;
  // Grow the run until it takes a tenth of the target, then scale it to the target.
  for (;;) {
    const double s =
        detail::wallSeconds(1, [&](unsigned) { sink = detail::fmaChains(iterations, 1); });
    if (s > 0.1 * seconds) {
      iterations = long(double(iterations) * seconds / s);
      break;
    }
    iterations *= 4;
  }
  double best = 0;
  for (int run = 0; run < 3; ++run) {
    const double s = detail::wallSeconds(
        threads, [&](unsigned t) { sink = detail::fmaChains(iterations, float(t)); });
    best = std::max(best, 2.0 * detail::kFmaLanes * double(iterations) * threads / s * 1e-9);
  }
  return best;
}

/// STREAM triad bandwidth of `threads` threads over three arrays of `doubles` each, GB/s, counted
/// as STREAM counts it (two reads and a write of 8 bytes per element); the best of five passes.
inline double triadGigabytesPerSecond(unsigned threads, std::size_t doubles = std::size_t(1)
                                                                              << 24) {
  std::vector<double> a(doubles, 0.0), b(doubles, 1.0), c(doubles, 2.0);
  const std::size_t chunk = (doubles + threads - 1) / threads;
  double best = 0;
  for (int pass = 0; pass < 5; ++pass) {
    const double s = detail::wallSeconds(threads, [&](unsigned t) {
      const std::size_t begin = std::min(doubles, t * chunk),
                        end = std::min(doubles, begin + chunk);
      double* pa = a.data();
      const double *pb = b.data(), *pc = c.data();
      for (std::size_t i = begin; i < end; ++i) pa[i] = pb[i] + 3.0 * pc[i];
    });
    best = std::max(best, 3.0 * 8.0 * double(doubles) / s * 1e-9);
  }
  volatile double sink = a[doubles / 2];
  (void)sink;
  return best;
}

}  // namespace lucent::bench
