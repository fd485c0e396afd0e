#pragma once
/// @file exit_lighting.hpp
/// @brief The light a random walk gathers where it leaves the object through a refracting boundary.
///
/// The volumetric truth lets the walk leave along its refracted direction, which a point or
/// directional light is never on: reaching it takes a manifold search from every scatter
/// (reference/manifold_next_event.hpp). Production random walks (Cycles, Arnold) replace the exit
/// direction by a diffuse lobe, so every light can be sampled from the exit point. This is that
/// lobe with the boundary's transmission, normalised to carry exactly the flux that leaves:
///   f(w) = Ft(eta, w) cos(w) / (pi c),  c = 1 - 2 C_1(external)  (fresnel_moments.hpp),
/// the exit law of Habel, Christensen and Jarosz 2013, Sec. 4. Under light L from every direction
/// the gathered value is L, so a white furnace stays white. What it gets wrong is the angular
/// shape of low scattering orders, whose exits are not diffuse.
///
/// Point and directional lights: one shadow ray each. Environments: one direction drawn from the
/// map and one from the lobe's cosine, weighed by the balance heuristic (Veach 1997, Sec. 9.2).
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <variant>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "../optics/constants.hpp"
#include "../optics/fresnel.hpp"
#include "../optics/fresnel_moments.hpp"
#include "../scene/environment_sampling.hpp"
#include "../scene/light.hpp"
#include "../scene/ray_caster.hpp"
#include "../util/basis.hpp"
#include "../util/rng.hpp"

namespace lucent::walk {

class ExitLighting {
 public:
  /// @param eta  the object's index relative to the surroundings (> 1: the boundary refracts)
  ExitLighting(const std::vector<scene::Light>& lights, const scene::RayCaster& caster, double eta)
      : mLights(lights),
        mCaster(caster),
        mEta(eta),
        mNormalisation(optics::exitNormalisation(eta)) {
    for (const scene::Light& light : mLights)  // the copy: samplers point into it
      if (const auto* env = std::get_if<scene::EnvironmentLight>(&light))
        mSamplers.push_back(std::make_unique<scene::EnvironmentSampler>(*env));
  }
  ExitLighting(const ExitLighting&) = delete;
  ExitLighting& operator=(const ExitLighting&) = delete;

  /// int L_i(w) f(w) dw at exit point x (already off the surface) with outward unit normal n: the
  /// radiance the walk carries back to where it entered, per unit of its weight. Environments are
  /// left out unless `withEnvironment` (a walk that goes on outside finds them along its path).
  glm::dvec3 gather(const glm::dvec3& x, const glm::dvec3& n, util::Rng& rng,
                    bool withEnvironment = true) const {
    glm::dvec3 sum(0);
    std::size_t env = 0;
    for (const scene::Light& light : mLights) {
      if (const auto sight = scene::deltaLightSight(light, x))
        sum += sight->irradiance * towardsLight(x, n, sight->toLight, sight->distance);
      else if (const auto* e = std::get_if<scene::EnvironmentLight>(&light); e && withEnvironment)
        sum += environment(*e, *mSamplers[env++], x, n, rng);
    }
    return sum;
  }

  const std::vector<scene::Light>& lights() const { return mLights; }

  /// The lobe's value f(w) for cos(w) = cosTheta.
  double lobe(double cosTheta) const {
    if (!(cosTheta > 0)) return 0;
    return optics::fresnelTransmittance(cosTheta, mEta) * cosTheta / (optics::kPi * mNormalisation);
  }

 private:
  static constexpr double kEndless = std::numeric_limits<double>::infinity();

  bool visible(const glm::dvec3& x, const glm::dvec3& u, double distance) const {
    return !mCaster.intersect(x, u, 0, distance);
  }

  /// f(u) for a delta light in direction u at `distance`, 0 when occluded or behind the surface.
  double towardsLight(const glm::dvec3& x, const glm::dvec3& n, const glm::dvec3& u,
                      double distance) const {
    const double f = lobe(glm::dot(n, u));
    return f > 0 && visible(x, u, distance) ? f : 0.0;
  }

  glm::dvec3 environment(const scene::EnvironmentLight& env, const scene::EnvironmentSampler& s,
                         const glm::dvec3& x, const glm::dvec3& n, util::Rng& rng) const {
    glm::dvec3 sum(0);
    if (s.valid()) {  // a direction drawn from the map
      double pdfMap = 0;
      const glm::dvec3 u = s.sample(rng.uniform(), rng.uniform(), rng.uniform(), pdfMap);
      const double cosU = glm::dot(n, u), f = lobe(cosU);
      if (f > 0 && pdfMap > 0 && visible(x, u, kEndless)) {
        const double pdfLobe = cosU / optics::kPi;
        sum += env.lookup(u) * (f / (pdfMap + pdfLobe));  // balance: w/p = 1/(p_map + p_lobe)
      }
    }
    // A direction drawn from the lobe's cosine.
    const double r = std::sqrt(rng.uniform()), phi = 2 * optics::kPi * rng.uniform();
    glm::dvec3 t, b;
    util::orthonormalBasis(n, t, b);
    const double cosU = std::sqrt(std::max(0.0, 1 - r * r));
    const glm::dvec3 u = glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * b + cosU * n);
    const double f = lobe(cosU), pdfLobe = cosU / optics::kPi;
    if (f > 0 && visible(x, u, kEndless))
      sum += env.lookup(u) * (f / (pdfLobe + (s.valid() ? s.pdf(u) : 0.0)));
    return sum;
  }

  const std::vector<scene::Light> mLights;
  const scene::RayCaster& mCaster;
  double mEta, mNormalisation;
  std::vector<std::unique_ptr<scene::EnvironmentSampler>> mSamplers;
};

}  // namespace lucent::walk
