#pragma once
/// @file radial_table_sum.hpp
/// @brief Stage 3 of Chang et al. 2008 (Sec. 3): B(x_o) = sum_i w_i f(|x_i - x_o|) over
/// the importance samples, f = Rd or a hybrid-weighted profile, looked up in a radial table exactly
/// as the GPU's 1-D texture does (u = sqrt(r / rMax), linear); also the truth's sum for the
/// profiles without a closed-form kernel (profile.hpp). Float, vectorised, cloned for AVX2 like the
/// truth's kernel; blocks of 1024 terms are added in double.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "../optics/dipole_lut.hpp"
#include "../util/simd.hpp"
#include "rd_sum_kernel.hpp"

namespace lucent::reference {

/// A radial table split into one float array per channel (gather-friendly).
struct PlanarRadialTable {
  std::vector<float> channel[3];
  float rMax = 0;

  explicit PlanarRadialTable(const optics::RadialTable<float>& table) : rMax(table.rMax()) {
    for (int c = 0; c < 3; ++c) {
      channel[c].reserve(table.size());
      for (const auto& v : table.values()) channel[c].push_back(v[c]);
    }
  }
  std::size_t size() const { return channel[0].size(); }
};

LUCENT_VECTOR_CLONES inline void radialTableSum(const RdKernelSamples& s,
                                                const PlanarRadialTable& table, float ox, float oy,
                                                float oz, double out[3]) {
  const float *x = s.x, *y = s.y, *z = s.z, *w0 = s.w0, *w1 = s.w1, *w2 = s.w2;
  const float *t0 = table.channel[0].data(), *t1 = table.channel[1].data(),
              *t2 = table.channel[2].data();
  const int last = int(table.size()) - 1;
  const float scale = float(last) / std::sqrt(table.rMax);
  const float limit = float(last);
  double total0 = 0, total1 = 0, total2 = 0;
  constexpr std::size_t kBlock = 1024;
  for (std::size_t begin = 0; begin < s.n; begin += kBlock) {
    const std::size_t end = std::min(s.n, begin + kBlock);
    float s0 = 0, s1 = 0, s2 = 0;
#pragma omp simd reduction(+ : s0, s1, s2)
    for (std::size_t i = begin; i < end; ++i) {
      const float dx = x[i] - ox, dy = y[i] - oy, dz = z[i] - oz;
      const float u =
          std::sqrt(std::sqrt(dx * dx + dy * dy + dz * dz)) * scale;  // sqrt(r / rMax) * last
      const float inside = u < limit ? 1.0f : 0.0f;                   // 0 beyond rMax
      const float uc = std::min(u, limit);
      const int k = std::min(int(uc), last - 1);
      const float f = uc - float(k);
      s0 += inside * w0[i] * (t0[k] + f * (t0[k + 1] - t0[k]));
      s1 += inside * w1[i] * (t1[k] + f * (t1[k + 1] - t1[k]));
      s2 += inside * w2[i] * (t2[k] + f * (t2[k + 1] - t2[k]));
    }
    total0 += s0, total1 += s1, total2 += s2;
  }
  out[0] = total0, out[1] = total1, out[2] = total2;
}

}  // namespace lucent::reference
