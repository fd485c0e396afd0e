#pragma once
/// @file light.hpp
/// @brief Light sources: point, directional, and an environment map (a lat-long or a cube-map
/// radiance image).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "../optics/constants.hpp"
#include "cube_map.hpp"

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

/// How an environment's texels cover the sphere of directions.
enum class EnvironmentLayout {
  /// Equirectangular: row 0 looks up (+y), column 0 looks towards -z, the columns turn towards +x
  /// (the layout of common HDR probes).
  LatLong,
  /// A cube map (cube_map.hpp): `width` texels across a face, the six faces stacked top to bottom
  /// in
  /// OpenGL's order, so `height` = 6 `width`.
  Cube,
};

/// Radiance arriving from every direction, stored as an image in one of the layouts above.
struct EnvironmentLight {
  int width = 0, height = 0;
  std::vector<glm::vec3> radiance;  ///< row-major, width*height
  double scale = 1;
  std::string source;
  EnvironmentLayout layout = EnvironmentLayout::LatLong;

  std::size_t texelCount() const { return std::size_t(width) * std::size_t(height); }

  /// The texel direction `dir` falls in (any length but zero).
  std::size_t texelOf(const glm::dvec3& dir) const {
    if (layout == EnvironmentLayout::Cube) return cube::texelIndex(dir, width);
    const double len = glm::length(dir);
    const double theta = std::acos(std::clamp(len > 0 ? dir.y / len : 1.0, -1.0, 1.0));
    double phi = std::atan2(dir.x, -dir.z);
    if (phi < 0) phi += 2 * optics::kPi;
    const int col = std::clamp(int(phi / (2 * optics::kPi) * width), 0, width - 1);
    const int row = std::clamp(int(theta / optics::kPi * height), 0, height - 1);
    return std::size_t(row) * width + col;
  }

  /// The exact solid angle of texel `i`; they sum to 4 pi.
  double texelSolidAngle(std::size_t i) const {
    const int row = int(i / std::size_t(width));
    if (layout == EnvironmentLayout::Cube)
      return cube::texelSolidAngle(row % width, int(i % width), width);
    const double cos0 = std::cos(optics::kPi * row / height);
    const double cos1 = std::cos(optics::kPi * (row + 1) / height);
    return 2 * optics::kPi / width * (cos0 - cos1);
  }

  glm::dvec3 lookup(const glm::dvec3& dir) const {
    if (width <= 0 || height <= 0) return glm::dvec3(0);
    return glm::dvec3(radiance[texelOf(dir)]) * scale;
  }

  /// The radiance averaged over the sphere, each texel by its solid angle (scale applied).
  glm::dvec3 meanRadiance() const {
    glm::dvec3 sum(0);
    for (std::size_t i = 0; i < radiance.size(); ++i)
      sum += glm::dvec3(radiance[i]) * texelSolidAngle(i);
    return sum * (scale / (4 * optics::kPi));
  }
};

using Light = std::variant<PointLight, DirectionalLight, EnvironmentLight>;

/// A point or directional light as seen from a point: the unit direction towards it, its distance
/// (infinite for a directional light) and the irradiance it gives normal to that direction.
struct DeltaLightSight {
  glm::dvec3 toLight{0}, irradiance{0};
  double distance = 0;
};

/// How `light` is seen from x; empty for an environment, or a point light at x itself.
inline std::optional<DeltaLightSight> deltaLightSight(const Light& light, const glm::dvec3& x) {
  if (const auto* p = std::get_if<PointLight>(&light)) {
    const glm::dvec3 v = p->position - x;
    const double d = glm::length(v);
    if (!(d > 0)) return std::nullopt;
    return DeltaLightSight{v / d, p->intensity / (d * d), d};
  }
  if (const auto* d = std::get_if<DirectionalLight>(&light))
    return DeltaLightSight{glm::normalize(d->towardLight), d->irradiance,
                           std::numeric_limits<double>::infinity()};
  return std::nullopt;
}

}  // namespace lucent::scene
