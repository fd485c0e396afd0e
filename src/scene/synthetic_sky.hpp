#pragma once
/// @file synthetic_sky.hpp
/// @brief A lat-long sky for examples and benchmarks that need an all-frequency light without a
/// file: a soft gradient brighter overhead and a small, very bright sun (3 x 3 texels of 128 x 64)
/// that casts sharp shadows and makes thin parts glow.
#include <algorithm>

#include <lucent/scene/light.hpp>

namespace lucent::scene {

inline EnvironmentLight syntheticSky() {
  EnvironmentLight env;
  env.width = 128, env.height = 64;
  env.source = "synthetic sky";
  for (int row = 0; row < env.height; ++row)
    for (int col = 0; col < env.width; ++col) {
      const float up = std::max(0.0f, 1.0f - 2.0f * float(row) / float(env.height));
      const bool sun = row >= 18 && row < 21 && col >= 80 && col < 83;
      env.radiance.push_back(glm::vec3(0.05f + 0.3f * up, 0.07f + 0.35f * up, 0.1f + 0.5f * up) +
                             (sun ? glm::vec3(300, 280, 240) : glm::vec3(0)));
    }
  return env;
}

}  // namespace lucent::scene
