#pragma once
/// @file rd_sum_kernel.hpp
/// @brief The inner loop of the brute-force truth: B(xo) = sum_i w_i Rd(|x_i - xo|) in three
/// channels, in float, vectorised (see fast_exp.hpp) and cloned for AVX2. Partial sums of 1024
/// terms are added in double, so rounding does not grow with the number of samples.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "../optics/constants.hpp"
#include "../optics/fast_exp.hpp"
#include "../optics/profile.hpp"
#include "../util/simd.hpp"

namespace lucent::reference {

/// The per-channel constants of a real and a virtual source in float (the classic and the better
/// dipole); a channel that does not scatter has k = kFluence = 0.
struct RdKernelConstants {
  float zr[3], zv[3], zr2[3], zv2[3], sigmaTr[3], k[3], kFluence[3];
  bool fluence = false;  ///< any kFluence != 0 (the better dipole); the classic skips those terms

  /// @pre profile.isPolePair()
  template <class T>
  static RdKernelConstants from(const optics::Profile<T>& profile) {
    RdKernelConstants c{};
    for (int i = 0; i < 3; ++i) {
      const auto& ch = profile.channel[i].poles;
      c.zr[i] = float(ch.zr), c.zv[i] = float(ch.zv), c.sigmaTr[i] = float(ch.sigmaTr);
      c.zr2[i] = c.zr[i] * c.zr[i], c.zv2[i] = c.zv[i] * c.zv[i];
      const double scale = double(ch.alphaPrime) / (4.0 * optics::kPi);
      c.k[i] = float(scale * double(ch.fluxWeight));
      c.kFluence[i] = float(scale * double(ch.fluenceWeight));
      c.fluence = c.fluence || c.kFluence[i] != 0.0f;
    }
    return c;
  }
  template <class T>
  static RdKernelConstants from(const optics::Dipole<T>& dipole) {
    return from(optics::Profile<T>(dipole));
  }
};

namespace detail {
/// Rd of one channel at squared distance r2 (Table 1): real source at depth zr, virtual at height
/// zv. A plain function of values (a capturing lambda here stops GCC from vectorising the loop).
template <bool kFluence>
LUCENT_ALWAYS_INLINE float rdChannel(float r2, const RdKernelConstants& k, int c) {
  const float zr = k.zr[c], zv = k.zv[c], st = k.sigmaTr[c];
  const float dr = std::sqrt(r2 + k.zr2[c]), dv = std::sqrt(r2 + k.zv2[c]);
  const float er = optics::expNonPositive(-st * dr), ev = optics::expNonPositive(-st * dv);
  const float flux = k.k[c] * (zr * (1.0f + st * dr) * er / (dr * dr * dr) +
                               zv * (1.0f + st * dv) * ev / (dv * dv * dv));
  if constexpr (!kFluence) return flux;
  return flux + k.kFluence[c] * (er / dr - ev / dv);  // the better dipole's fluence term
}
}  // namespace detail

/// Samples as structure-of-arrays; w0..w2 are E_i A_i per channel.
struct RdKernelSamples {
  const float *x, *y, *z, *w0, *w1, *w2;
  std::size_t n;
};

/// Growable float arrays in the kernels' layout, for sums whose terms are gathered per point (the
/// octree's sources, the ring filter's taps). Growing keeps what was gathered.
struct GatheredSamples {
  static constexpr int kArrays = 6;
  std::vector<float> array[kArrays];  ///< x, y, z, w0, w1, w2

  void fit(std::size_t n) {
    if (array[0].size() < n)
      for (auto& a : array) a.resize(std::max<std::size_t>(2 * n, 1024));
  }
  template <class Position, class Weight>
  void set(std::size_t i, const Position& x, const Weight& w) {
    array[0][i] = float(x.x), array[1][i] = float(x.y), array[2][i] = float(x.z);
    array[3][i] = float(w.x), array[4][i] = float(w.y), array[5][i] = float(w.z);
  }
  /// The first n entries, as the kernels take them.
  RdKernelSamples view(std::size_t n) const {
    return {array[0].data(),
            array[1].data(),
            array[2].data(),
            array[3].data(),
            array[4].data(),
            array[5].data(),
            n};
  }
};

namespace detail {
// Always inlined, so that it is compiled for each of rdSumFloat's target clones.
template <bool kFluence>
LUCENT_ALWAYS_INLINE void rdSumFloatLoop(const RdKernelSamples& s, const RdKernelConstants& k,
                                         float ox, float oy, float oz, double out[3]) {
  // Locals, not struct members, inside the loop: GCC will not vectorise loads through s.x etc.
  // because a float store could (as far as it knows) change the pointers.
  const float *x = s.x, *y = s.y, *z = s.z, *w0 = s.w0, *w1 = s.w1, *w2 = s.w2;
  const RdKernelConstants kc = k;
  double total0 = 0, total1 = 0, total2 = 0;
  constexpr std::size_t kBlock = 1024;
  for (std::size_t begin = 0; begin < s.n; begin += kBlock) {
    const std::size_t end = std::min(s.n, begin + kBlock);
    float s0 = 0, s1 = 0, s2 = 0;
#pragma omp simd reduction(+ : s0, s1, s2)
    for (std::size_t i = begin; i < end; ++i) {
      const float dx = x[i] - ox, dy = y[i] - oy, dz = z[i] - oz;
      const float r2 = dx * dx + dy * dy + dz * dz;
      s0 += w0[i] * rdChannel<kFluence>(r2, kc, 0);
      s1 += w1[i] * rdChannel<kFluence>(r2, kc, 1);
      s2 += w2[i] * rdChannel<kFluence>(r2, kc, 2);
    }
    total0 += s0, total1 += s1, total2 += s2;
  }
  out[0] = total0, out[1] = total1, out[2] = total2;
}
}  // namespace detail

LUCENT_VECTOR_CLONES inline void rdSumFloat(const RdKernelSamples& s, const RdKernelConstants& k,
                                            float ox, float oy, float oz, double out[3]) {
  if (k.fluence)
    detail::rdSumFloatLoop<true>(s, k, ox, oy, oz, out);
  else
    detail::rdSumFloatLoop<false>(s, k, ox, oy, oz, out);
}

}  // namespace lucent::reference
