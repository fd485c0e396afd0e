#pragma once
/// @file irradiance.hpp
/// @brief Irradiance transmitted into the surface, E(x) = int L_i(w) Ft(eta, w) |n.w| dw
/// (Chang et al. 2008 Eq. 4), with shadows, for every kind of light.
#include <cmath>
#include <cstdint>
#include <limits>
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
  double rayEpsilon = 1e-4;  ///< mm; shadow rays start this far off the surface (scale it with the object)
  int environmentStrata = 16;///< the environment is sampled with strata x strata cosine-weighted directions
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

/// @param point surface position (mm); @param normal shading normal; @param faceNormal geometric normal
/// (both unit, outward); @param sampleId seeds the environment jitter.
inline glm::dvec3 irradianceAt(const glm::dvec3& point, const glm::dvec3& normal, const glm::dvec3& faceNormal,
                               const std::vector<Light>& lights, const RayCaster& caster,
                               const IrradianceSettings& settings, std::uint64_t sampleId = 0) {
  const glm::dvec3 origin = point + faceNormal * settings.rayEpsilon;
  glm::dvec3 e(0);
  auto transmitted = [&](const glm::dvec3& towardLight) {
    const double cosN = glm::dot(normal, towardLight);
    if (cosN <= 0 || glm::dot(faceNormal, towardLight) <= 0) return 0.0;
    return cosN * optics::fresnelTransmittance(cosN, settings.eta);
  };
  for (const Light& light : lights) {
    if (const auto* p = std::get_if<PointLight>(&light)) {
      const glm::dvec3 d = p->position - origin;
      const double dist2 = glm::dot(d, d);
      if (!(dist2 > 0)) continue;
      const double dist = std::sqrt(dist2);
      const glm::dvec3 w = d / dist;
      const double f = transmitted(w);
      if (f > 0 && !caster.occluded(origin, w, 0, dist)) e += p->intensity * (f / dist2);
    } else if (const auto* dl = std::get_if<DirectionalLight>(&light)) {
      const glm::dvec3 w = glm::normalize(dl->towardLight);
      const double f = transmitted(w);
      if (f > 0 && !caster.occluded(origin, w, 0, std::numeric_limits<double>::infinity())) e += dl->irradiance * f;
    } else if (const auto* env = std::get_if<EnvironmentLight>(&light)) {
      // Cosine-weighted stratified directions: pdf = cos/pi, so E ~= (pi/N) sum L Ft.
      glm::dvec3 t, b;
      util::orthonormalBasis(normal, t, b);
      const int k = std::max(1, settings.environmentStrata);
      glm::dvec3 sum(0);
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
          const std::uint64_t id = sampleId * 0x9E3779B97F4A7C15ULL + std::uint64_t(i * k + j);
          const double u1 = (i + detail::hashToUnit(id * 2 + 1)) / k;
          const double u2 = (j + detail::hashToUnit(id * 2 + 2)) / k;
          const double r = std::sqrt(u1), phi = 2 * optics::kPi * u2;
          const double cosT = std::sqrt(std::max(0.0, 1 - u1));
          const glm::dvec3 w = r * std::cos(phi) * t + r * std::sin(phi) * b + cosT * normal;
          if (glm::dot(faceNormal, w) <= 0) continue;
          if (caster.occluded(origin, w, 0, std::numeric_limits<double>::infinity())) continue;
          sum += env->lookup(w) * optics::fresnelTransmittance(cosT, settings.eta);
        }
      e += sum * (optics::kPi / double(k * k));
    }
  }
  return e;
}

}  // namespace lucent::scene
