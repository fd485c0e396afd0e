#pragma once
/// @file volume_path_tracer.hpp
/// @brief The physical truth: unbiased volumetric path tracing of the radiative transfer equation
/// inside the closed surfaces of a MediumScene (homogeneous or density-field media, nested bodies,
/// cavities, Fresnel or null interfaces, HG phase), RGB with hero-channel MIS.
///
/// How each kind of light is reached:
/// - environment: camera paths that leave the scene look it up (every scattering order);
/// - point and directional lights, every interface index-matched: next-event estimation from each
///   scattering vertex, through null interfaces (every order);
/// - point and directional lights behind a refracting interface (the default, Manifold): from each
///   scattering vertex, next-event estimation straight (through null interfaces) and through one
///   refraction (manifold_next_event.hpp), every scattering order; light that also reflected on its
///   way in comes by light subpaths (light_subpaths.hpp) joined to each camera segment at a point
///   drawn by equiangular sampling (Kulla & Fajardo 2012), whose pdf cancels the 1/d^2 of the join.
///   Of those, paths whose every scatter-to-scatter edge is specular cannot be sampled.
/// - the same with DeltaLightStrategy::Joins: light subpaths for all of it (no single scattering).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "../image/image.hpp"
#include "../optics/dipole.hpp"
#include "../scene/camera.hpp"
#include "../scene/surface_clearance_grid.hpp"
#include "../util/parallel.hpp"
#include "../util/sample_mean.hpp"
#include "hero_choice.hpp"
#include "light_subpaths.hpp"
#include "manifold_next_event.hpp"
#include "medium_flight.hpp"
#include "segment_transmittance.hpp"

namespace lucent::reference {

class VolumePathTracer {
 public:
  VolumePathTracer(const MediumScene& scene, const scene::RayCaster& caster,
                   const std::vector<scene::Light>& lights, const PathTracerSettings& settings)
      : mScene(scene),
        mCaster(caster),
        mSettings(settings),
        mLights(lights),
        mClearance(scene.mesh) {
    const scene::Bounds b = scene.mesh.bounds();
    mCentre = b.center();
    mRadius = 0.5 * b.diagonal() * 1.01 + 1e-9;
    const bool matched = scene.indexMatched();
    for (const scene::Light& light : mLights) {  // the copy: emitters point into it
      LightEmitter e;
      if (const auto* p = std::get_if<scene::PointLight>(&light)) {
        e.kind = LightEmitter::Kind::Point, e.position = p->position, e.power = p->intensity;
      } else if (const auto* d = std::get_if<scene::DirectionalLight>(&light)) {
        e.kind = LightEmitter::Kind::Directional, e.towards = glm::normalize(d->towardLight),
        e.power = d->irradiance;
      } else {
        const auto& env = std::get<scene::EnvironmentLight>(light);
        if (settings.environment == EnvironmentStrategy::Escape) {
          mEscape.push_back(&env);
          continue;
        }
        e.kind = LightEmitter::Kind::Environment, e.environment = &env;
        e.sampler.emplace(env);
        if (!e.sampler->valid()) continue;
        mJoined.push_back(std::move(e));
        continue;
      }
      if (matched) {
        mNextEvent.push_back(std::move(e));
      } else if (settings.deltaLights == DeltaLightStrategy::Manifold) {
        e.cameraReachesThroughOneRefraction = true;
        mNextEvent.push_back(e);
        mJoined.push_back(std::move(e));
      } else {
        mJoined.push_back(std::move(e));
      }
    }
    if (!matched && !mNextEvent.empty())
      mManifold.emplace(scene, caster, std::max(0, settings.manifoldGap));
    mGuideRadius = settings.guideRadius > 0 ? settings.guideRadius : autoGuideRadius();
    if (settings.heroChoice == HeroChoice::Reflectance) mHeroChoice = reflectanceHeroChoice(scene);
  }

  /// P_c, the probability of each channel being a path's hero.
  const glm::dvec3& heroChoice() const { return mHeroChoice; }

  /// True when delta lights reach scattering vertices through a refraction by a manifold search.
  bool manifoldDeltaLights() const { return mManifold.has_value(); }
  /// True when delta lights are reached by light subpaths (some interface refracts).
  bool joinsDeltaLights() const {
    for (const auto& e : mJoined)
      if (e.kind != LightEmitter::Kind::Environment) return true;
    return false;
  }
  double guideRadius() const { return mGuideRadius; }

  /// One estimate of the radiance arriving at `origin` from `direction` (origin outside every
  /// body).
  glm::dvec3 sample(const glm::dvec3& origin, const glm::dvec3& direction, util::Rng& rng,
                    PathTracerStats& st) const {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const PathTracerSettings& s = mSettings;
    ++st.cameraSamples;
    HeroChannelWeight w;
    w.choice = mHeroChoice;
    const int hero = w.pickHero(rng.uniform());
    glm::dvec3 radiance(0), pos = origin, dir = direction;
    // A distant camera's rays start near the scene: Embree's float hit distances scale with the
    // origin's.
    if (glm::length(pos - mCentre) > 2 * mRadius)
      pos += std::max(0.0, glm::dot(mCentre - pos, dir) - 2 * mRadius) * dir;
    std::uint32_t medium = 0;
    int scatters = 0;
    double radianceScale = 1;  // the product of the crossings' (n1/n2)^2, for roulette
    bool straightEdge = false, specularSinceScatter = false, firstSurface = true;
    std::vector<LightVertex> targets;
    for (std::uint64_t events = 0;; ++events) {
      if (events >= s.maxEvents) {
        ++st.truncatedPaths;
        break;
      }
      const Medium& m = mScene.media[medium];
      std::optional<scene::RayHit> hit;
      if (!m.vacuum()) {
        // Joins need the whole segment, so they always cast.
        MediumFlight flight;
        if (!flight.begin(m, mCaster, mClearance, pos, dir, hero, rng, s.rayEpsilon,
                          !targets.empty(), st))
          break;
        hit = flight.hit;
        if (!targets.empty())
          radiance += joinAlongSegment(pos, dir, hit->t, medium, w, scatters + 1, targets, rng, st);
        if (flight.collides(m, pos, dir, hero, rng, w, st.medium)) {
          pos += flight.t * dir;
          ++scatters, ++st.scatterEvents;
          if (scatters > 1 && !specularSinceScatter) straightEdge = true;
          specularSinceScatter = false;
          if (!mNextEvent.empty() && orderCounts(s.orders, scatters))
            radiance += nextEventEstimate(pos, dir, medium, w, rng, st);
          if (!survivesRoulette(w, radianceScale, scatters, rng)) {
            ++st.rouletteTerminations;
            break;
          }
          dir = scatterHG(dir, m.g, rng);
          continue;
        }
      } else if (!(hit = mCaster.intersect(pos, dir, 0, kInf))) {
        if (orderCounts(s.orders, scatters) && (!s.connectableOnly || straightEdge))
          for (const auto* env : mEscape) radiance += w.value() * env->lookup(dir);
        break;
      }
      const glm::dvec3 point = surfacePoint(mScene, *hit);
      const InterfaceSides sides = interfaceSides(mScene, hit->triangle, dir);
      if (sides.from != medium && hit->t < 4 * s.rayEpsilon) {
        // The path stands within rounding of a facet, on its far side (a scatter a few nanometres
        // from the boundary): step past it rather than cross from the wrong medium.
        pos += (hit->t + s.rayEpsilon) * dir;
        continue;
      }
      if (sides.from != medium) ++st.mediumMismatches;
      const InterfaceCrossing c = crossInterface(mScene, point, dir, sides, s.rayEpsilon, rng, true,
                                                 firstSurface && s.subsurfaceOnly);
      if (firstSurface) traceLightSubpaths(point, hero, rng, targets, st);
      firstSurface = false;
      if (c.weight <= 0) break;
      w.scale(glm::dvec3(c.weight));
      radianceScale *= c.radianceScale;
      specularSinceScatter |= c.specular;
      pos = c.origin, dir = c.direction, medium = c.medium;
    }
    if (!std::isfinite(radiance.x + radiance.y + radiance.z)) {
      ++st.nonFiniteSamples;
      return glm::dvec3(0);
    }
    return radiance;
  }

 private:
  double autoGuideRadius() const {
    // 1 / sigma_tr of the first medium, averaged over channels, between one and ten transport mean
    // free paths: without absorption 1/sigma_tr is infinite, and aiming light entries over the
    // whole object left a 100 m spectralon sphere black (the camera's walk ends within a few mean
    // free paths of its entry). The disc's pdf is a mixture with a uniform part: any scale is
    // unbiased.
    const Medium* m = firstMedium(mScene);
    if (!m) return mRadius;
    const glm::dvec3 sigmaTPrime = m->sigmaA + (1 - m->g) * m->sigmaS;
    const glm::dvec3 sigmaTr = glm::sqrt(3.0 * m->sigmaA * sigmaTPrime);
    const double meanTr = (sigmaTr.x + sigmaTr.y + sigmaTr.z) / 3,
                 meanT = (sigmaTPrime.x + sigmaTPrime.y + sigmaTPrime.z) / 3;
    const double meanFreePath = meanT > 0 ? 1 / meanT : mRadius;
    const double length =
        std::clamp(meanTr > 0 ? 1 / meanTr : mRadius, meanFreePath, 10 * meanFreePath);
    return std::min(length, mRadius);
  }

  void traceLightSubpaths(const glm::dvec3& entry, int hero, util::Rng& rng,
                          std::vector<LightVertex>& targets, PathTracerStats& st) const {
    const std::size_t first = targets.size();
    for (const LightEmitter& e : mJoined)
      for (int i = 0; i < mSettings.lightSubpaths; ++i)
        traceLightSubpath(
            mScene, mCaster, sampleEmission(e, mCentre, mRadius, entry, mGuideRadius, rng), hero,
            mHeroChoice, mSettings, rng, targets, st, e.cameraReachesThroughOneRefraction);
    for (std::size_t i = first; i < targets.size(); ++i)
      targets[i].weight.scale(glm::dvec3(1.0 / mSettings.lightSubpaths));
  }

  glm::dvec3 segmentTransmittance(const glm::dvec3& x, std::uint32_t medium, const glm::dvec3& dir,
                                  double length, std::optional<std::uint32_t> endMedium,
                                  util::Rng& rng, PathTracerStats& st,
                                  SegmentEnd* end = nullptr) const {
    return reference::segmentTransmittance(mScene, mCaster, mSettings.rayEpsilon, x, medium, dir,
                                           length, endMedium, rng, st, end);
  }

  glm::dvec3 nextEventEstimate(const glm::dvec3& x, const glm::dvec3& dirIn, std::uint32_t medium,
                               const HeroChannelWeight& w, util::Rng& rng,
                               PathTracerStats& st) const {
    glm::dvec3 sum(0);
    const double g = mScene.media[medium].g;
    for (const LightEmitter& e : mNextEvent) {
      glm::dvec3 toLight = e.towards, irradiance = e.power;
      double distance = std::numeric_limits<double>::infinity();
      if (e.kind == LightEmitter::Kind::Point) {
        const glm::dvec3 v = e.position - x;
        distance = glm::length(v);
        toLight = v / distance;
        irradiance = e.power / (distance * distance);
      }
      SegmentEnd end;
      const glm::dvec3 tr =
          segmentTransmittance(x, medium, toLight, distance, std::nullopt, rng, st, &end);
      // Light travels along -toLight, then towards the camera along -dirIn.
      sum += w.value() * irradiance * tr * optics::phaseHG(glm::dot(toLight, dirIn), g);
      if (mManifold) sum += w.value() * throughOneRefraction(x, dirIn, medium, e, end, rng, st);
    }
    return sum;
  }

  /// The light scattered at x towards -dirIn that reached x through one refraction, summed over
  /// the refraction points the manifold search finds, each checked for visibility on both sides.
  /// `straight` is where the straight segment to the light ended: the search starts from its
  /// refracting facet instead of casting the same ray again.
  glm::dvec3 throughOneRefraction(const glm::dvec3& x, const glm::dvec3& dirIn,
                                  std::uint32_t medium, const LightEmitter& e,
                                  const SegmentEnd& straight, util::Rng& rng,
                                  PathTracerStats& st) const {
    thread_local std::vector<RefractedConnection> found;
    found.clear();
    if (straight.reachedEnd || straight.refractingFacet)
      mManifold->searchFrom(straight.refractingFacet, x, e, found, st.manifold);
    else
      mManifold->search(x, e, mSettings.rayEpsilon, found, st.manifold);
    glm::dvec3 sum(0);
    const double g = mScene.media[medium].g;
    for (const RefractedConnection& c : found) {
      // Look for occluders short of the facet (the float hit distance of its own plane is not
      // exact), and attenuate over the rest up to it in the facet's inner medium.
      const double inside = std::max(0.0, c.insideLength * (1 - 1e-5) - 4 * mSettings.rayEpsilon);
      glm::dvec3 trIn = segmentTransmittance(x, medium, c.towardsPoint, inside, c.inner, rng, st);
      if (maxComponent(trIn) <= 0) continue;
      if (const Medium& m = mScene.media[c.inner]; !m.vacuum())
        trIn *= transmittance(m, x + inside * c.towardsPoint, c.towardsPoint,
                              c.insideLength - inside, rng, st.medium);
      const glm::dvec3 trOut =
          segmentTransmittance(c.point + mSettings.rayEpsilon * c.normalOut, c.outer,
                               c.towardsLight, c.outsideLength, std::nullopt, rng, st);
      sum += e.power * c.irradiancePerPower * trIn * trOut *
             optics::phaseHG(glm::dot(c.towardsPoint, dirIn), g);
    }
    return sum;
  }

  /// Joins every light vertex to the camera segment (pos, dir, [0, tMax]) at a point sampled with
  /// pdf proportional to 1/d^2 from the light vertex (equiangular sampling).
  glm::dvec3 joinAlongSegment(const glm::dvec3& pos, const glm::dvec3& dir, double tMax,
                              std::uint32_t medium, const HeroChannelWeight& w, int cameraOrder,
                              const std::vector<LightVertex>& targets, util::Rng& rng,
                              PathTracerStats& st) const {
    const Medium& m = mScene.media[medium];
    glm::dvec3 sum(0);
    for (const LightVertex& z : targets) {
      if (!orderCounts(mSettings.orders, cameraOrder + z.order)) continue;
      const double along = glm::dot(z.position - pos, dir);
      const double h = std::max(glm::length(z.position - (pos + along * dir)), 1e-9 * mRadius);
      const double a = std::atan2(-along, h), b = std::atan2(tMax - along, h);
      if (!(b > a)) continue;
      const double t = std::clamp(along + h * std::tan(a + (b - a) * rng.uniform()), 0.0, tMax);
      const double pdf = h / ((b - a) * (h * h + (t - along) * (t - along)));
      const glm::dvec3 x = pos + t * dir, toZ = z.position - x;
      const double d2 = glm::dot(toZ, toZ);
      if (!(d2 > 0) || !(pdf > 0)) continue;
      const double d = std::sqrt(d2);
      const glm::dvec3 u = toZ / d;
      ++st.connections;
      const glm::dvec3 trLink = segmentTransmittance(x, medium, u, d, z.medium, rng, st);
      if (maxComponent(trLink) <= 0) continue;
      const glm::dvec3 trCamera = transmittance(m, pos, dir, t, rng, st.medium);
      const glm::dvec3 sigmaS =
          m.homogeneous() ? m.sigmaS : detail::localCoefficients(m, x, st.medium).sigmaS;
      const double phases = optics::phaseHG(glm::dot(u, dir), m.g) *
                            optics::phaseHG(glm::dot(z.directionIn, -u), mScene.media[z.medium].g);
      const glm::dvec3 link = trCamera * sigmaS * trLink * (phases / (d2 * pdf));
      sum += HeroChannelWeight::joined(w, z.weight, link);
    }
    return sum;
  }

  const MediumScene& mScene;
  const scene::RayCaster& mCaster;
  PathTracerSettings mSettings;
  const std::vector<scene::Light> mLights;
  glm::dvec3 mCentre{0};
  double mRadius = 1, mGuideRadius = 1;
  glm::dvec3 mHeroChoice{1.0 / 3};
  std::vector<const scene::EnvironmentLight*> mEscape;
  std::vector<LightEmitter> mNextEvent, mJoined;
  std::optional<ManifoldNextEvent> mManifold;
  scene::SurfaceClearanceGrid mClearance;  ///< lets flights that end deep inside skip a ray cast
};

struct PathTracedImage {
  image::Image image;  ///< mean radiance; alpha 1 where the pixel's centre ray meets the scene
  image::Image standardError;  ///< per-pixel standard error of the mean, per channel
  PathTracerStats stats;
};

/// Renders with `samplesPerPixel` estimates per pixel along its centre ray (the pixel footprint of
/// the dipole references, so images compare pixel by pixel). Deterministic for a fixed seed: each
/// pixel has its own generator, whatever the thread count.
inline PathTracedImage renderPathTraced(const VolumePathTracer& tracer,
                                        const scene::RayCaster& caster,
                                        const scene::PinholeCamera& camera,
                                        const PathTracerSettings& s,
                                        const util::ParallelFor& parallelFor = util::serialFor,
                                        const util::Progress& progress = {}) {
  PathTracedImage out;
  out.image = image::Image(camera.width, camera.height);
  out.standardError = image::Image(camera.width, camera.height);
  std::mutex statsMutex;
  std::atomic<int> rowsDone{0};
  const int spp = std::max(1, s.samplesPerPixel);
  parallelFor(std::size_t(camera.height), [&](std::size_t begin, std::size_t end) {
    PathTracerStats local;
    for (std::size_t row = begin; row < end; ++row) {
      for (int col = 0; col < camera.width; ++col) {
        const scene::Ray ray = camera.primaryRay(col, double(row));
        if (!caster.intersect(ray.origin, ray.direction, 0,
                              std::numeric_limits<double>::infinity()))
          continue;
        const std::size_t pixel = row * std::size_t(camera.width) + std::size_t(col);
        util::Rng rng(s.seed * 1000003ULL + pixel);
        util::SampleMean estimate;
        for (int i = 0; i < spp; ++i)
          estimate.add(tracer.sample(ray.origin, ray.direction, rng, local));
        out.image.pixels[pixel] = glm::vec4(glm::vec3(estimate.mean()), 1.0f);
        out.standardError.pixels[pixel] = glm::vec4(glm::vec3(estimate.standardError()), 1.0f);
      }
      if (progress) progress(double(++rowsDone) / camera.height);
    }
    const std::lock_guard<std::mutex> lock(statsMutex);
    out.stats.add(local);
  });
  return out;
}

}  // namespace lucent::reference
