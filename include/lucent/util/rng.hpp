#pragma once
/// @file rng.hpp
/// @brief A small, fast, reproducible random number generator (xoshiro256+, seeded by splitmix64), so
/// that Monte Carlo results are identical for a fixed seed on every platform and thread count.
#include <cstdint>

namespace lucent::util {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) {
    for (auto& s : mState) s = splitmix(seed);
  }
  /// Uniform in [0, 1).
  double uniform() {
    const std::uint64_t result = mState[0] + mState[3];
    const std::uint64_t t = mState[1] << 17;
    mState[2] ^= mState[0];
    mState[3] ^= mState[1];
    mState[1] ^= mState[2];
    mState[0] ^= mState[3];
    mState[2] ^= t;
    mState[3] = (mState[3] << 45) | (mState[3] >> 19);
    return double(result >> 11) * (1.0 / 9007199254740992.0);
  }

 private:
  static std::uint64_t splitmix(std::uint64_t& x) {
    std::uint64_t z = (x += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  std::uint64_t mState[4];
};

}  // namespace lucent::util
