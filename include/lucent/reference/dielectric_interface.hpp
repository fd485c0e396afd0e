#pragma once
/// @file dielectric_interface.hpp
/// @brief What happens where a path meets a surface of a MediumScene: a smooth Fresnel dielectric
/// between the media on either side (reflect or refract, chosen by the exact Fresnel probability),
/// or a null interface where both indices agree (the path passes straight on). Shared by every
/// subpath the volume path tracer builds, and by its connections.
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "../optics/fresnel.hpp"
#include "../scene/ray_caster.hpp"
#include "../util/rng.hpp"
#include "participating_media.hpp"

namespace lucent::reference {

struct InterfaceCrossing {
  glm::dvec3 origin, direction;  ///< where and how the path goes on (origin nudged off the surface)
  std::uint32_t medium = 0;      ///< the medium it goes on in
  bool specular = false;         ///< reflected or refracted (a null interface is not specular)
  double weight = 1;             ///< factor on the path's contribution (0 = the path ends)
  /// The part of `weight` that is radiance scaling, (n1/n2)^2 on a refraction of a camera path:
  /// exiting undoes it, so it is no loss of throughput (Russian roulette must not read it as one).
  double radianceScale = 1;
};

/// The two media a triangle separates, seen from a path travelling along `direction`.
struct InterfaceSides {
  std::uint32_t from, to;
  glm::dvec3 normalTowardsPath;  ///< unit geometric normal on the side the path comes from
};

inline InterfaceSides interfaceSides(const MediumScene& scene, std::uint32_t triangle,
                                     const glm::dvec3& direction) {
  const glm::dvec3 n = glm::normalize(scene.mesh.areaVector(triangle));
  const bool fromOutside = glm::dot(direction, n) < 0;
  return fromOutside ? InterfaceSides{scene.outside[triangle], scene.inside[triangle], n}
                     : InterfaceSides{scene.inside[triangle], scene.outside[triangle], -n};
}

/// The hit point from the triangle's barycentrics, in double: origin + t * direction carries the
/// float error of t, which for a ray from a distant light exceeds a micrometre object's size.
inline glm::dvec3 surfacePoint(const MediumScene& scene, const scene::RayHit& hit) {
  const glm::uvec3 tri = scene.mesh.triangles[hit.triangle];
  return (1 - hit.u - hit.v) * glm::dvec3(scene.mesh.positions[tri.x]) +
         hit.u * glm::dvec3(scene.mesh.positions[tri.y]) +
         hit.v * glm::dvec3(scene.mesh.positions[tri.z]);
}

/// @param radiance  true on camera subpaths: refraction from index n1 into n2 scales the carried
/// radiance
///                  by (n1/n2)^2 (L/n^2 is what is conserved along a ray); light subpaths carry
///                  flux.
/// @param forceTransmit  refract with weight Ft instead of choosing (a "subsurface only" first
/// hit).
inline InterfaceCrossing crossInterface(const MediumScene& scene, const glm::dvec3& point,
                                        const glm::dvec3& direction, const InterfaceSides& sides,
                                        double epsilon, util::Rng& rng, bool radiance,
                                        bool forceTransmit = false) {
  const glm::dvec3& nf = sides.normalTowardsPath;
  const double n1 = scene.media[sides.from].eta, n2 = scene.media[sides.to].eta;
  InterfaceCrossing out;
  if (n1 == n2) {
    out.origin = point - epsilon * nf;
    out.direction = direction;
    out.medium = sides.to;
    return out;
  }
  out.specular = true;
  const double cosI = std::min(1.0, std::max(0.0, -glm::dot(direction, nf)));
  const double reflectance = optics::fresnelReflectance(cosI, n2 / n1);
  bool reflect = false;
  if (forceTransmit)
    out.weight = 1 - reflectance;
  else
    reflect = rng.uniform() < reflectance;
  if (reflect || reflectance >= 1) {
    if (forceTransmit) out.weight = 0;
    out.origin = point + epsilon * nf;
    out.direction = glm::normalize(direction + 2 * cosI * nf);
    out.medium = sides.from;
    return out;
  }
  const double ratio = n1 / n2;
  const double cosT = std::sqrt(std::max(0.0, 1 - ratio * ratio * (1 - cosI * cosI)));
  out.origin = point - epsilon * nf;
  out.direction = glm::normalize(ratio * direction + (ratio * cosI - cosT) * nf);
  out.medium = sides.to;
  if (radiance) out.radianceScale = ratio * ratio, out.weight *= out.radianceScale;
  return out;
}

}  // namespace lucent::reference
