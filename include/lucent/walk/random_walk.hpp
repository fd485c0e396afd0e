#pragma once
/// @file random_walk.hpp
/// @brief Random-walk subsurface scattering, the way production renderers do it (Cycles' and
/// Arnold's random walk; Chiang, Kutz, Burley 2016): from the visible surface point the path
/// refracts in (weight Ft), walks the medium with the path tracer's own flights (closed form when
/// homogeneous, delta tracking otherwise, hero channel with spectral MIS, inclusions crossed as
/// Fresnel dielectrics), and where it leaves through the refracting boundary it gathers point and
/// directional light through a diffuse exit lobe (exit_lighting.hpp): the refracted direction it
/// leaves along never meets a delta light, which the truth reaches by a manifold search from every
/// scatter (reference/volume_path_tracer.hpp).
///
/// Against that truth the lobe is the approximation, and only where the object's boundary refracts:
/// - exit=fresnel (default): at the boundary the walk reflects back inside or leaves with the
///   Fresnel probabilities, as the truth does; where it leaves it gathers the delta lights through
///   the lobe and goes on outside, so the environment it escapes to and light that re-enters the
///   object (a concave shape) are counted as the path tracer counts them. With env-exit=lobe the
///   environment is gathered through the lobe too (multiple importance sampling of the map: less
///   noise under a probe with a sun, the lobe's bias).
/// - exit=first: the walk leaves at the first boundary it meets and gathers every light through
///   the lobe (Cycles); internal reflection, which keeps light inside longer, and light through
///   other parts of the object are left out.
/// Where the boundary is index-matched nothing is approximated: delta lights are reached by
/// next-event estimation from every scatter and the environment by the paths that leave, as in the
/// path tracer. Bodies inside a cavity are not told from the surroundings (lucent's scenes have
/// none): leaving one counts as an exit.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <variant>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "../reference/dielectric_interface.hpp"
#include "../reference/hero_choice.hpp"
#include "../reference/medium_flight.hpp"
#include "../reference/segment_transmittance.hpp"
#include "../scene/surface_clearance_grid.hpp"
#include "exit_lighting.hpp"

namespace lucent::walk {

/// Where a walk that meets the refracting boundary leaves.
enum class ExitRule { Fresnel, First };

struct RandomWalkSettings {
  /// Events per walk before it is dropped (counted): the path tracer's limit.
  std::uint64_t maxEvents = reference::PathTracerSettings{}.maxEvents;
  ExitRule exit = ExitRule::Fresnel;
  /// exit=fresnel: the environment gathered through the lobe at exits (else found by escaping).
  bool environmentByLobe = false;
  reference::HeroChoice heroChoice = reference::HeroChoice::Reflectance;
  double rayEpsilon = 1e-6;  ///< mm: offset of new rays off a surface
};

struct RandomWalkStats {
  reference::PathTracerStats paths;       ///< walks (cameraSamples), scatters, roulette, leaks, ...
  std::uint64_t exits = 0;                ///< exits through the refracting boundary (lobe gathers)
  std::uint64_t internalReflections = 0;  ///< Fresnel reflections back inside (exit=fresnel)
  void add(const RandomWalkStats& o) {
    paths.add(o.paths);
    exits += o.exits, internalReflections += o.internalReflections;
  }
};

class RandomWalk {
 public:
  /// `scene`: medium 0 around the object, whose body comes first (its medium is the one the hero
  /// choice reads); `caster` over scene.mesh.
  RandomWalk(const reference::MediumScene& scene, const scene::RayCaster& caster,
             const std::vector<scene::Light>& lights, const RandomWalkSettings& settings)
      : mScene(scene),
        mCaster(caster),
        mSettings(settings),
        mExit(lights, caster, objectEta(scene)),
        mClearance(scene.mesh),
        mMatched(objectEta(scene) == 1) {
    if (settings.heroChoice == reference::HeroChoice::Reflectance)
      mHeroChoice = reference::reflectanceHeroChoice(scene);
  }

  const glm::dvec3& heroChoice() const { return mHeroChoice; }
  const ExitLighting& exitLighting() const { return mExit; }

  /// One estimate of the radiance leaving surface point `point` of triangle `triangle` against
  /// `direction` (the direction the eye looks along): the subsurface part, without the surface's
  /// own reflection.
  glm::dvec3 sample(const glm::dvec3& point, std::uint32_t triangle, const glm::dvec3& direction,
                    util::Rng& rng, RandomWalkStats& st) const {
    ++st.paths.cameraSamples;
    reference::HeroChannelWeight w;
    w.choice = mHeroChoice;
    const int hero = w.pickHero(rng.uniform());
    const reference::InterfaceSides sides = reference::interfaceSides(mScene, triangle, direction);
    if (sides.from != 0) return glm::dvec3(0);  // seen from inside the object: nothing to enter
    const reference::InterfaceCrossing in = reference::crossInterface(
        mScene, point, direction, sides, mSettings.rayEpsilon, rng, false, true);
    if (in.weight <= 0) return glm::dvec3(0);
    w.scale(glm::dvec3(in.weight));
    const glm::dvec3 l = walk(in.origin, in.direction, in.medium, hero, w, rng, st);
    if (!std::isfinite(l.x + l.y + l.z)) {
      ++st.paths.nonFiniteSamples;
      return glm::dvec3(0);
    }
    return l;
  }

 private:
  static double objectEta(const reference::MediumScene& scene) {
    return scene.media.size() > 1 ? scene.media[1].eta / scene.media[0].eta : 1.0;
  }

  /// What a walk meeting a surface does next.
  enum class Step { Continue, End };

  /// The walk from `pos` along `dir` in `medium` (radiance scaling left out: the entry's and the
  /// exit's cancel, and roulette reads the weight as throughput).
  glm::dvec3 walk(glm::dvec3 pos, glm::dvec3 dir, std::uint32_t medium, int hero,
                  reference::HeroChannelWeight& w, util::Rng& rng, RandomWalkStats& st) const {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const double eps = mSettings.rayEpsilon;
    glm::dvec3 radiance(0);
    int scatters = 0;
    for (std::uint64_t events = 0;; ++events) {
      if (events >= mSettings.maxEvents) {
        ++st.paths.truncatedPaths;
        break;
      }
      const reference::Medium& m = mScene.media[medium];
      std::optional<scene::RayHit> hit;
      if (!m.vacuum()) {
        reference::MediumFlight flight;
        if (!flight.begin(m, mCaster, mClearance, pos, dir, hero, rng, eps, false, st.paths)) break;
        hit = flight.hit;
        if (flight.collides(m, pos, dir, hero, rng, w, st.paths.medium)) {
          pos += flight.t * dir;
          ++scatters, ++st.paths.scatterEvents;
          if (mMatched) radiance += w.value() * nextEventFromScatter(pos, dir, medium, rng, st);
          if (!reference::survivesRoulette(w, 1, scatters, rng)) {
            ++st.paths.rouletteTerminations;
            break;
          }
          dir = reference::scatterHG(dir, m.g, rng);
          continue;
        }
      } else if (!(hit = mCaster.intersect(pos, dir, 0, kInf))) {
        // Once scattered, every refracting exit gathered through the lobe: with env-exit=lobe the
        // environment was counted there.
        if (mMatched || !mSettings.environmentByLobe || scatters == 0)
          radiance += w.value() * escaping(dir);
        break;
      }
      if (atSurface(*hit, scatters, pos, dir, medium, w, radiance, rng, st) == Step::End) break;
    }
    return radiance;
  }

  /// The walk at a surface it reached: it crosses or reflects as the truth does, gathering the
  /// lobe's light where it leaves through the refracting boundary (exit=first: and ends there).
  Step atSurface(const scene::RayHit& hit, int scatters, glm::dvec3& pos, glm::dvec3& dir,
                 std::uint32_t& medium, reference::HeroChannelWeight& w, glm::dvec3& radiance,
                 util::Rng& rng, RandomWalkStats& st) const {
    const double eps = mSettings.rayEpsilon;
    const glm::dvec3 point = reference::surfacePoint(mScene, hit);
    const reference::InterfaceSides sides = reference::interfaceSides(mScene, hit.triangle, dir);
    if (sides.from != medium && hit.t < 4 * eps) {
      pos += (hit.t + eps) * dir;  // a scatter within rounding of the far side: step past it
      return Step::Continue;
    }
    if (sides.from != medium) ++st.paths.mediumMismatches;
    const bool leaving = sides.to == 0 && sides.from == mScene.inside[hit.triangle];
    const double n1 = mScene.media[sides.from].eta, n2 = mScene.media[sides.to].eta;
    // A walk that has not scattered leaves along the camera's refracted ray, which meets no delta
    // light: the lobe stands for scattered light only (without this rule a thin sheet, crossed
    // unscattered, gathered the light behind it as if it had diffused: 3.7 times the truth).
    const bool refractingExit = leaving && n1 != n2 && scatters > 0;
    const glm::dvec3 outward = -sides.normalTowardsPath, outside = point + eps * outward;
    if (refractingExit && mSettings.exit == ExitRule::First) {
      ++st.exits;
      radiance += w.value() * mExit.gather(outside, outward, rng);
      return Step::End;
    }
    const reference::InterfaceCrossing c =
        reference::crossInterface(mScene, point, dir, sides, eps, rng, false);
    if (refractingExit && c.medium == sides.to) {
      ++st.exits;
      radiance += w.value() * mExit.gather(outside, outward, rng, mSettings.environmentByLobe);
    } else if (refractingExit) {
      ++st.internalReflections;
    }
    if (c.weight <= 0) return Step::End;
    w.scale(glm::dvec3(c.weight));
    pos = c.origin, dir = c.direction, medium = c.medium;
    return Step::Continue;
  }

  /// The environment seen along `dir` by a walk that left the object.
  glm::dvec3 escaping(const glm::dvec3& dir) const {
    glm::dvec3 sum(0);
    for (const scene::Light& light : mExit.lights())
      if (const auto* env = std::get_if<scene::EnvironmentLight>(&light)) sum += env->lookup(dir);
    return sum;
  }

  /// Point and directional light scattered at x towards -dirIn, reached straight through
  /// index-matched boundaries (the path tracer's next-event estimation).
  glm::dvec3 nextEventFromScatter(const glm::dvec3& x, const glm::dvec3& dirIn,
                                  std::uint32_t medium, util::Rng& rng, RandomWalkStats& st) const {
    glm::dvec3 sum(0);
    const double g = mScene.media[medium].g;
    for (const scene::Light& light : mExit.lights()) {
      const auto sight = scene::deltaLightSight(light, x);
      if (!sight) continue;  // environments: by the paths that leave
      const glm::dvec3 tr = reference::segmentTransmittance(
          mScene, mCaster, mSettings.rayEpsilon, x, medium, sight->toLight, sight->distance,
          std::nullopt, rng, st.paths);
      sum += sight->irradiance * tr * optics::phaseHG(glm::dot(sight->toLight, dirIn), g);
    }
    return sum;
  }

  const reference::MediumScene& mScene;
  const scene::RayCaster& mCaster;
  RandomWalkSettings mSettings;
  ExitLighting mExit;                      ///< holds the lights
  scene::SurfaceClearanceGrid mClearance;  ///< lets flights that end deep inside skip a ray cast
  bool mMatched;  ///< the object's boundary does not refract: nothing is approximated
  glm::dvec3 mHeroChoice{1.0 / 3};
};

}  // namespace lucent::walk
