#pragma once
/// @file embree_ray_caster.hpp
/// @brief scene::RayCaster on Embree 3: a BVH over the mesh, thread-safe single-ray queries and
/// ray streams.
#include <memory>

#include <lucent/scene/mesh.hpp>
#include <lucent/scene/ray_caster.hpp>

namespace lucent::raycast {

class EmbreeRayCaster final : public scene::RayCaster {
 public:
  explicit EmbreeRayCaster(const scene::TriangleMesh& mesh);
  ~EmbreeRayCaster() override;
  EmbreeRayCaster(const EmbreeRayCaster&) = delete;
  EmbreeRayCaster& operator=(const EmbreeRayCaster&) = delete;

  std::optional<scene::RayHit> intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                                         double tMin, double tMax) const override;
  bool occluded(const glm::dvec3& origin, const glm::dvec3& direction, double tMin,
                double tMax) const override;
  /// The rays as one coherent stream (rtcOccluded1M), which Embree traces in packets.
  void occludedMany(const scene::ShadowRay* rays, std::size_t n, bool* blocked) const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> mImpl;
};

}  // namespace lucent::raycast
