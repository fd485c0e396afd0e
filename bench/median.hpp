#pragma once
// The median the benchmarks report (robust to the odd slow run on a shared machine): the upper
// middle of an even count, NaN for no values.
#include <algorithm>
#include <cmath>
#include <vector>

namespace lucent::bench {

inline double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace lucent::bench
