#pragma once
/// @file irradiance.hpp
/// @brief Irradiance transmitted into the surface, E(x) = int L_i(w) Ft(eta, w) |n.w| dw
/// (Chang et al. 2008 Eq. 4), with shadows, for every kind of light.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <variant>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "../optics/fresnel.hpp"
#include "../util/basis.hpp"
#include "light.hpp"
#include "ray_caster.hpp"

namespace lucent::scene {

struct IrradianceSettings {
  double eta = 1.3;
  double rayEpsilon =
      1e-4;  ///< mm; shadow rays start this far off the surface (scale it with the object)
  int environmentStrata =
      16;  ///< the environment is sampled with strata x strata cosine-weighted directions
};

namespace detail {
/// A small integer hash: deterministic per-sample jitter, so images are reproducible run to run.
inline double hashToUnit(std::uint64_t x) {
  x ^= x >> 33;
  x *= 0xff51afd7ed558ccdULL;
  x ^= x >> 33;
  x *= 0xc4ceb9fe1a85ec53ULL;
  x ^= x >> 33;
  return double(x >> 11) * (1.0 / 9007199254740992.0);
}

}  // namespace detail

/// What a point or directional light gives a surface point if its shadow ray is unblocked.
struct ShadowedTerm {
  ShadowRay ray;
  glm::dvec3 irradiance{0};
};

namespace detail {
/// Where a point's shadow rays start: off the surface along the face normal, so that they do not
/// hit the point's own triangle.
inline glm::dvec3 shadowRayOrigin(const glm::dvec3& point, const glm::dvec3& faceNormal,
                                  const IrradianceSettings& settings) {
  return point + faceNormal * settings.rayEpsilon;
}

/// cos * Ft for light arriving from towardLight: 0 from behind the shading or the face normal.
inline double transmittedCosine(const glm::dvec3& normal, const glm::dvec3& faceNormal,
                                const glm::dvec3& towardLight, double eta) {
  const double cosN = glm::dot(normal, towardLight);
  if (cosN <= 0 || glm::dot(faceNormal, towardLight) <= 0) return 0.0;
  return cosN * optics::fresnelTransmittance(cosN, eta);
}

/// The shadow ray and term of a point or directional light at origin; nothing when the light is
/// behind the surface (or an environment, which irradianceFromEnvironment handles).
inline std::optional<ShadowedTerm> shadowedTerm(const Light& light, const glm::dvec3& origin,
                                                const glm::dvec3& normal,
                                                const glm::dvec3& faceNormal, double eta) {
  if (const auto* p = std::get_if<PointLight>(&light)) {
    const glm::dvec3 d = p->position - origin;
    const double dist2 = glm::dot(d, d);
    if (!(dist2 > 0)) return std::nullopt;
    const double dist = std::sqrt(dist2);
    const glm::dvec3 w = d / dist;
    const double f = transmittedCosine(normal, faceNormal, w, eta);
    if (!(f > 0)) return std::nullopt;
    return ShadowedTerm{{origin, w, dist}, p->intensity * (f / dist2)};
  }
  if (const auto* dl = std::get_if<DirectionalLight>(&light)) {
    const glm::dvec3 w = glm::normalize(dl->towardLight);
    const double f = transmittedCosine(normal, faceNormal, w, eta);
    if (!(f > 0)) return std::nullopt;
    return ShadowedTerm{{origin, w, std::numeric_limits<double>::infinity()}, dl->irradiance * f};
  }
  return std::nullopt;
}

/// Cosine-weighted stratified directions: pdf = cos/pi, so E ~= (pi/N) sum L Ft.
inline glm::dvec3 irradianceFromEnvironment(const EnvironmentLight& env, const glm::dvec3& origin,
                                            const glm::dvec3& normal, const glm::dvec3& faceNormal,
                                            const RayCaster& caster,
                                            const IrradianceSettings& settings,
                                            std::uint64_t sampleId) {
  glm::dvec3 t, b;
  util::orthonormalBasis(normal, t, b);
  const int k = std::max(1, settings.environmentStrata);
  glm::dvec3 sum(0);
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const std::uint64_t id = sampleId * 0x9E3779B97F4A7C15ULL + std::uint64_t(i * k + j);
      const double u1 = (i + hashToUnit(id * 2 + 1)) / k;
      const double u2 = (j + hashToUnit(id * 2 + 2)) / k;
      const double r = std::sqrt(u1), phi = 2 * optics::kPi * u2;
      const double cosT = std::sqrt(std::max(0.0, 1 - u1));
      const glm::dvec3 w = r * std::cos(phi) * t + r * std::sin(phi) * b + cosT * normal;
      if (glm::dot(faceNormal, w) <= 0) continue;
      if (caster.occluded(origin, w, 0, std::numeric_limits<double>::infinity())) continue;
      sum += env.lookup(w) * optics::fresnelTransmittance(cosT, settings.eta);
    }
  return sum * (optics::kPi / double(k * k));
}
}  // namespace detail

/// @param point surface position (mm); @param normal shading normal; @param faceNormal geometric
/// normal (both unit, outward); @param sampleId seeds the environment jitter.
inline glm::dvec3 irradianceAt(const glm::dvec3& point, const glm::dvec3& normal,
                               const glm::dvec3& faceNormal, const std::vector<Light>& lights,
                               const RayCaster& caster, const IrradianceSettings& settings,
                               std::uint64_t sampleId = 0) {
  const glm::dvec3 origin = detail::shadowRayOrigin(point, faceNormal, settings);
  glm::dvec3 e(0);
  for (const Light& light : lights) {
    if (const auto* env = std::get_if<EnvironmentLight>(&light))
      e += detail::irradianceFromEnvironment(*env, origin, normal, faceNormal, caster, settings,
                                             sampleId);
    else if (const auto term =
                 detail::shadowedTerm(light, origin, normal, faceNormal, settings.eta))
      if (!caster.occluded(term->ray.origin, term->ray.direction, 0, term->ray.tMax))
        e += term->irradiance;
  }
  return e;
}

/// A surface point as irradianceMany reads it (the arguments of irradianceAt).
struct SurfacePoint {
  glm::dvec3 position, normal, faceNormal;
  std::uint64_t sampleId = 0;
};

/// irradianceAt at the points pointAt(0..n-1) into out[0, n): the same terms added in the same
/// order, so equal to it point by point wherever the caster's occludedMany answers as its
/// occluded does. The shadow rays of the point and directional lights are cast together through
/// RayCaster::occludedMany, so that Embree traces neighbouring points' rays as packets; an
/// environment's rays are cast one at a time. @param pointAt callable std::size_t -> SurfacePoint.
template <class PointAt>
void irradianceMany(std::size_t n, const PointAt& pointAt, const std::vector<Light>& lights,
                    const RayCaster& caster, const IrradianceSettings& settings, glm::dvec3* out) {
  const std::size_t perPoint = lights.size();
  std::vector<glm::dvec3> term(n * perPoint, glm::dvec3(0));
  std::vector<SurfacePoint> points(n);
  std::vector<glm::dvec3> origins(n);
  for (std::size_t k = 0; k < n; ++k) {
    points[k] = pointAt(k);
    origins[k] = detail::shadowRayOrigin(points[k].position, points[k].faceNormal, settings);
  }
  // Light by light, so that consecutive rays (which Embree packs into packets) share a light.
  std::vector<ShadowRay> rays;
  std::vector<std::size_t> termOfRay;
  rays.reserve(n * perPoint);
  termOfRay.reserve(n * perPoint);
  for (std::size_t l = 0; l < perPoint; ++l)
    for (std::size_t k = 0; k < n; ++k) {
      const SurfacePoint& p = points[k];
      glm::dvec3& t = term[k * perPoint + l];
      if (const auto* env = std::get_if<EnvironmentLight>(&lights[l])) {
        t = detail::irradianceFromEnvironment(*env, origins[k], p.normal, p.faceNormal, caster,
                                              settings, p.sampleId);
      } else if (const auto s = detail::shadowedTerm(lights[l], origins[k], p.normal, p.faceNormal,
                                                     settings.eta)) {
        t = s->irradiance;
        rays.push_back(s->ray);
        termOfRay.push_back(k * perPoint + l);
      }
    }
  std::unique_ptr<bool[]> blocked(new bool[rays.size()]);
  caster.occludedMany(rays.data(), rays.size(), blocked.get());
  for (std::size_t r = 0; r < rays.size(); ++r)
    if (blocked[r]) term[termOfRay[r]] = glm::dvec3(0);
  for (std::size_t k = 0; k < n; ++k) {
    glm::dvec3 e(0);
    for (std::size_t l = 0; l < perPoint; ++l) e += term[k * perPoint + l];
    out[k] = e;
  }
}

}  // namespace lucent::scene
