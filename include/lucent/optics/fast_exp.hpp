#pragma once
/// @file fast_exp.hpp
/// @brief exp(x) for x <= 0 in float, written without calls, branches or int-float conversions of
/// unknown range, so that loops using it vectorise (std::exp is a library call, which blocks that).
/// Cephes' expf: x = n ln2 + r with n = round(x log2 e) (by the 1.5*2^23 trick), |r| <= ln2/2, a
/// degree-6 polynomial for e^r, and 2^n built in the exponent bits. Max relative error 3e-7 on
/// [-87, 0] (tests/unit/test_fast_exp.cpp checks it against std::exp); x < -87 gives exp(-87)
/// ~ 1.6e-38, x > 0 gives 1. Vectorisation also needs -fno-trapping-math, which lucent::core sets.
#include <cstdint>
#include <cstring>

#include "../util/simd.hpp"

namespace lucent::optics {

/// Always inlined: a call to it left in a kernel's loop stops the loop's vectorisation.
LUCENT_ALWAYS_INLINE float expNonPositive(float x) {
  x = x < -87.0f ? -87.0f : x;
  x = x > 0.0f ? 0.0f : x;
  constexpr float kRoundMagic =
      12582912.0f;  // 1.5 * 2^23: adding and subtracting it rounds to an integer
  const float n = (x * 1.44269504088896341f + kRoundMagic) - kRoundMagic;
  const float r =
      x - n * 0.693359375f - n * -2.12194440e-4f;  // ln2 split in two for exact reduction
  const float z = r * r;
  const float p = ((((((1.9875691500e-4f * r + 1.3981999507e-3f) * r + 8.3334519073e-3f) * r +
                      4.1665795894e-2f) *
                         r +
                     1.6666665459e-1f) *
                        r +
                    5.0000001201e-1f) *
                   z) +
                  r + 1.0f;
  const std::int32_t bits = (std::int32_t(n) + 127) << 23;
  float scale;
  std::memcpy(&scale, &bits, sizeof scale);
  return p * scale;
}

}  // namespace lucent::optics
