#pragma once
/// @file radial_table_sum.hpp
/// @brief Stage 3 of Chang et al. 2008 (Sec. 3): B(x_o) = sum_i w_i f(|x_i - x_o|) over
/// the importance samples, f = Rd or a hybrid-weighted profile, looked up in a radial table exactly
/// as the GPU's 1-D texture does (u = sqrt(r / rMax), linear); also the truth's sum for the
/// profiles without a closed-form kernel (profile.hpp). Float, vectorised; blocks of 1024 terms are
/// added in double. On a CPU with AVX-512 the sum reads each term's node as one record
/// (radial_table_sum_avx512.hpp); elsewhere it gathers per channel, cloned for AVX2 like the
/// truth's kernel.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "../optics/dipole_lut.hpp"
#include "../util/simd.hpp"
#include "radial_table_node.hpp"
#include "radial_table_sum_avx512.hpp"
#include "rd_sum_kernel.hpp"

namespace lucent::reference {

/// A radial table in the two layouts the sums read: one float array per channel (for per-channel
/// gathers) and one record per node (value and slope of the three channels, for one load a term).
struct PlanarRadialTable {
  std::vector<float> channel[3];
  std::vector<RadialTableNode> nodes;
  float rMax = 0;

  explicit PlanarRadialTable(const optics::RadialTable<float>& table) : rMax(table.rMax()) {
    if (table.size() < 2)
      throw std::invalid_argument("PlanarRadialTable: a table needs two nodes to interpolate");
    for (int c = 0; c < 3; ++c) {
      channel[c].reserve(table.size());
      for (const auto& v : table.values()) channel[c].push_back(v[c]);
    }
    nodes.resize(table.size());
    for (std::size_t k = 0; k < table.size(); ++k)
      for (int c = 0; c < 3; ++c) {
        nodes[k].value[c] = channel[c][k];
        nodes[k].slope[c] = k + 1 < table.size() ? channel[c][k + 1] - channel[c][k] : 0.0f;
      }
  }
  std::size_t size() const { return channel[0].size(); }
  /// The node index of u = sqrt(r / rMax) * (size - 1) is u * lookupScale() (see the sums).
  float lookupScale() const { return float(size() - 1) / std::sqrt(rMax); }
};

/// Adds the terms [begin, end) to total, gathering each channel's two nodes.
LUCENT_VECTOR_CLONES inline void radialTableSumGathered(const RdKernelSamples& s,
                                                        const PlanarRadialTable& table, float ox,
                                                        float oy, float oz, std::size_t begin,
                                                        std::size_t end, double total[3]) {
  const float *x = s.x, *y = s.y, *z = s.z, *w0 = s.w0, *w1 = s.w1, *w2 = s.w2;
  const float *t0 = table.channel[0].data(), *t1 = table.channel[1].data(),
              *t2 = table.channel[2].data();
  const int last = int(table.size()) - 1;
  const float scale = table.lookupScale();
  const float limit = float(last);
  for (std::size_t blockBegin = begin; blockBegin < end; blockBegin += kTableSumBlock) {
    const std::size_t blockEnd = std::min(end, blockBegin + kTableSumBlock);
    float s0 = 0, s1 = 0, s2 = 0;
#pragma omp simd reduction(+ : s0, s1, s2)
    for (std::size_t i = blockBegin; i < blockEnd; ++i) {
      const float dx = x[i] - ox, dy = y[i] - oy, dz = z[i] - oz;
      const float u =
          std::sqrt(std::sqrt(dx * dx + dy * dy + dz * dz)) * scale;  // sqrt(r / rMax) * last
      const float inside = u < limit ? 1.0f : 0.0f;                   // 0 beyond rMax
      const float uc = std::min(limit, u);  // NaN -> limit (and inside = 0), as on AVX-512
      const int k = std::min(int(uc), last - 1);
      const float f = uc - float(k);
      s0 += inside * w0[i] * (t0[k] + f * (t0[k + 1] - t0[k]));
      s1 += inside * w1[i] * (t1[k] + f * (t1[k + 1] - t1[k]));
      s2 += inside * w2[i] * (t2[k] + f * (t2[k + 1] - t2[k]));
    }
    total[0] += s0, total[1] += s1, total[2] += s2;
  }
}

/// B(x_o) into out, by the fastest path this CPU has.
inline void radialTableSum(const RdKernelSamples& s, const PlanarRadialTable& table, float ox,
                           float oy, float oz, double out[3]) {
  out[0] = out[1] = out[2] = 0;
  std::size_t done = 0;
#if LUCENT_HAS_AVX512_TABLE_SUM
  if (cpuHasAvx512())
    done = radialTableSumAvx512(s, table.nodes.data(), int(table.size()) - 1, table.lookupScale(),
                                ox, oy, oz, out);
#endif
  radialTableSumGathered(s, table, ox, oy, oz, done, s.n, out);
}

}  // namespace lucent::reference
