#pragma once
/// @file ray_caster.hpp
/// @brief The ray-casting interface the core uses for visibility; implemented with Embree in src/raycast.
#include <cstdint>
#include <optional>

#include <glm/vec3.hpp>

namespace lucent::scene {

struct RayHit {
  double t = 0;
  std::uint32_t triangle = 0;
  double u = 0, v = 0;  ///< barycentrics of vertices 1 and 2
};

class RayCaster {
 public:
  virtual ~RayCaster() = default;
  /// Nearest hit with t in (tMin, tMax), if any. Thread-safe.
  virtual std::optional<RayHit> intersect(const glm::dvec3& origin, const glm::dvec3& direction, double tMin,
                                          double tMax) const = 0;
  /// Whether anything is hit with t in (tMin, tMax). Thread-safe.
  virtual bool occluded(const glm::dvec3& origin, const glm::dvec3& direction, double tMin, double tMax) const = 0;
};

}  // namespace lucent::scene
