#pragma once
/// @file ray_caster.hpp
/// @brief The ray-casting interface the core uses for visibility; implemented with Embree in
/// src/raycast.
#include <cstdint>
#include <limits>
#include <optional>

#include <glm/geometric.hpp>
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
  virtual std::optional<RayHit> intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                                          double tMin, double tMax) const = 0;
  /// Whether anything is hit with t in (tMin, tMax). Thread-safe.
  virtual bool occluded(const glm::dvec3& origin, const glm::dvec3& direction, double tMin,
                        double tMax) const = 0;
};

/// Whether p lies inside the closed surface `caster` holds: an odd number of crossings along a
/// fixed, axis-free direction (hits closer than epsilon to the last are the same crossing).
inline bool insideByParity(const RayCaster& caster, glm::dvec3 p, double epsilon) {
  int crossings = 0;
  const glm::dvec3 dir = glm::normalize(glm::dvec3(1, 0.0123, 0.0321));
  for (int i = 0; i < 10000; ++i) {
    const auto hit = caster.intersect(p, dir, epsilon, std::numeric_limits<double>::infinity());
    if (!hit) break;
    ++crossings;
    p += hit->t * dir;
  }
  return crossings % 2 == 1;
}

}  // namespace lucent::scene
