#pragma once
/// @file environment_image.hpp
/// @brief An environment light from an image as a user gives it (an EXR probe): the check of its
/// texels, and the layout read from its shape. One spelling for every front end (the CLI's
/// env:FILE.exr, the VTK filter's EnvironmentFileName).
#include <cmath>
#include <sstream>
#include <string>

#include "environment_resample.hpp"

namespace lucent::scene {

/// The brightest light lucent takes: irradiance, radiance or scale per channel; far below where
/// sums of many lights and samples could overflow a double.
inline constexpr double kMaxLightValue = 1e12;

/// The first texel whose radiance is negative, not finite or above kMaxLightValue, as "texel (x,
/// y) has radiance V; ..."; empty when every texel is fine. `pixel(x, y)` reads radiance.
template <class PixelAt>
std::string environmentTexelProblem(int width, int height, PixelAt&& pixel) {
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::dvec3 p(pixel(x, y));
      for (int c = 0; c < 3; ++c)
        if (!(std::isfinite(p[c]) && p[c] >= 0 && p[c] <= kMaxLightValue)) {
          std::ostringstream o;
          o << "texel (" << x << ", " << y << ") has radiance " << p[c]
            << "; an environment map needs finite values in [0, 1e12]";
          return o.str();
        }
    }
  return {};
}

/// A cube map when the image has the shape of a layout of cube_layouts.hpp (6N x N, N x 6N, 4N x
/// 3N, 3N x 4N); otherwise a lat-long probe (2:1 usually, though any shape maps).
template <class PixelAt>
EnvironmentLight environmentFromImage(int width, int height, PixelAt&& pixel) {
  if (const auto layout = cube::detectLayout(width, height))
    return cubeFromImage(*layout, cube::faceSize(*layout, width, height), pixel);
  EnvironmentLight env;
  env.width = width, env.height = height;
  env.radiance.reserve(env.texelCount());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) env.radiance.push_back(glm::vec3(pixel(x, y)));
  return env;
}

}  // namespace lucent::scene
