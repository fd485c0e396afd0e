#pragma once
/// @file light.hpp
/// @brief Light sources: point, directional, and an environment map (lat-long radiance image).
#include <algorithm>
#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "../optics/constants.hpp"

namespace lucent::scene {

/// Radiant intensity (W/sr per channel) at a position (mm): irradiance I cos / d^2.
struct PointLight {
  glm::dvec3 position{0};
  glm::dvec3 intensity{1};
};

/// Parallel light arriving from `towardLight` with irradiance `irradiance` on a surface facing it.
struct DirectionalLight {
  glm::dvec3 towardLight{0, 0, 1};
  glm::dvec3 irradiance{1};
};

/// Radiance arriving from every direction, stored as an equirectangular (lat-long) image: row 0 looks up
/// (+y), column 0 looks towards -z, the columns turn towards +x (the layout of common HDR probes).
struct EnvironmentLight {
  int width = 0, height = 0;
  std::vector<glm::vec3> radiance;  ///< row-major, width*height
  double scale = 1;
  std::string source;

  glm::dvec3 lookup(const glm::dvec3& dir) const {
    if (width <= 0 || height <= 0) return glm::dvec3(0);
    const double theta = std::acos(std::clamp(dir.y, -1.0, 1.0));
    double phi = std::atan2(dir.x, -dir.z);
    if (phi < 0) phi += 2 * optics::kPi;
    const int col = std::min(width - 1, int(phi / (2 * optics::kPi) * width));
    const int row = std::min(height - 1, int(theta / optics::kPi * height));
    return glm::dvec3(radiance[std::size_t(row) * width + col]) * scale;
  }
};

using Light = std::variant<PointLight, DirectionalLight, EnvironmentLight>;

}  // namespace lucent::scene
