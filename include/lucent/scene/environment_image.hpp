#pragma once
/// @file environment_image.hpp
/// @brief An environment light from an image as a user gives it (an EXR probe): the check of its
/// texels, and the layout read from its shape. One spelling for every front end (the CLI's
/// env:FILE.exr, the VTK filter's EnvironmentFileName).
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "environment_resample.hpp"

namespace lucent::scene {

/// The brightest light lucent takes: irradiance, radiance or scale per channel; far below where
/// sums of many lights and samples could overflow a double.
inline constexpr double kMaxLightValue = 1e12;

/// The largest share of a map's energy (the sum of its texels' absolute values, all channels) that
/// negative texels may carry and be clamped to 0; above it the map is refused. Real probes carry
/// -1e-5 against 1-1000 elsewhere from filtering and lossy compression (shares near 1e-9); 0.1 %
/// is far below any technique's error, so clamping changes no result that matters.
inline constexpr double kNegligibleEnergyShare = 1e-3;

/// The texels of a probe as lucent lights with them, and what screening did: negative texels that
/// carry a negligible share of the energy and NaN texels that are a negligible share of the
/// texels are clamped to 0 (`note` says how many and their share); anything else is `problem`.
struct ScreenedTexels {
  std::vector<glm::vec3> radiance;  ///< row-major, width x height, every value in [0, 1e12]
  std::string note;                 ///< one line when texels were clamped; empty otherwise
  std::string problem;              ///< why the map is refused; empty when it is taken
};

namespace detail {
inline std::string texelLine(int x, int y, double value, const std::string& why) {
  std::ostringstream o;
  o << "texel (" << x << ", " << y << ") has radiance " << value << "; " << why;
  return o.str();
}
}  // namespace detail

/// Screens a probe's radiance `pixel(x, y)`. Refused: an infinite texel or one above
/// kMaxLightValue (its energy is not negligible), NaN in more than kNegligibleEnergyShare of the
/// texels, or negative texels carrying more than kNegligibleEnergyShare of the energy.
template <class PixelAt>
ScreenedTexels screenEnvironmentTexels(int width, int height, PixelAt&& pixel) {
  ScreenedTexels out;
  out.radiance.reserve(std::size_t(width) * std::size_t(height));
  double total = 0, negative = 0;
  std::size_t negatives = 0, nans = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      glm::vec3 p(pixel(x, y));
      for (int c = 0; c < 3; ++c) {
        if (std::isnan(p[c])) {
          ++nans, p[c] = 0;
        } else if (!(std::fabs(p[c]) <= kMaxLightValue)) {
          if (out.problem.empty())
            out.problem = detail::texelLine(
                x, y, p[c], "an environment map needs finite values of at most 1e12");
        } else if (p[c] < 0) {
          ++negatives, negative -= p[c], total -= p[c], p[c] = 0;
        } else {
          total += p[c];
        }
      }
      out.radiance.push_back(p);
    }
  if (!out.problem.empty()) return out;
  const std::size_t values = 3 * out.radiance.size();
  std::ostringstream o;
  if (double(nans) > kNegligibleEnergyShare * double(values))
    o << nans << " of " << values << " texel values are NaN (more than "
      << 100 * kNegligibleEnergyShare << " %); an environment map needs finite values";
  else if (negative > kNegligibleEnergyShare * total)
    o << negatives << " negative texel values carry " << 100 * negative / total
      << " % of the map's energy (more than " << 100 * kNegligibleEnergyShare
      << " % is not filtering noise); an environment map needs values of at least 0";
  out.problem = o.str();
  if (!out.problem.empty() || negatives + nans == 0) return out;
  std::ostringstream n;
  n << "clamped " << negatives + nans << " texel values to 0: " << negatives
    << " negative (a share " << (total > 0 ? negative / total : 0.0)
    << " of the map's energy, at most " << kNegligibleEnergyShare << " is clamped) and " << nans
    << " NaN";
  out.note = n.str();
  return out;
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

/// The environment light of a probe's screened texels (environmentFromImage over them).
inline EnvironmentLight environmentFromTexels(int width, int height, const ScreenedTexels& texels) {
  return environmentFromImage(width, height, [&](int x, int y) {
    return texels.radiance[std::size_t(y) * std::size_t(width) + std::size_t(x)];
  });
}

}  // namespace lucent::scene
