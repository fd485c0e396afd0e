#pragma once
/// @file ray_caster.hpp
/// @brief The ray-casting interface the core uses for visibility; implemented with Embree in
/// src/raycast.
#include <cstddef>
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

/// A visibility query: is anything hit with t in (0, tMax) from origin along the unit direction?
struct ShadowRay {
  glm::dvec3 origin{0}, direction{0, 0, 1};
  double tMax = std::numeric_limits<double>::infinity();
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
  /// occluded(ray.origin, ray.direction, 0, ray.tMax) for n rays at once, into blocked[0, n): a
  /// caster may trace them as a stream (Embree's packets), which pays when they are coherent, e.g.
  /// the shadow rays of neighbouring texels toward one light. Thread-safe.
  virtual void occludedMany(const ShadowRay* rays, std::size_t n, bool* blocked) const {
    for (std::size_t i = 0; i < n; ++i)
      blocked[i] = occluded(rays[i].origin, rays[i].direction, 0, rays[i].tMax);
  }
};

/// Another caster's single-ray queries only: its occludedMany falls back to one occluded() a ray
/// (the baseline that shadow_ray_bench and the stream tests hold the streams to).
class OneRayAtATime final : public RayCaster {
 public:
  explicit OneRayAtATime(const RayCaster& inner) : mInner(inner) {}
  std::optional<RayHit> intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                                  double tMin, double tMax) const override {
    return mInner.intersect(origin, direction, tMin, tMax);
  }
  bool occluded(const glm::dvec3& origin, const glm::dvec3& direction, double tMin,
                double tMax) const override {
    return mInner.occluded(origin, direction, tMin, tMax);
  }

 private:
  const RayCaster& mInner;
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
