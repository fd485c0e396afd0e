#pragma once
/// @file light_subpaths.hpp
/// @brief Light subpaths for delta lights behind a refracting boundary. A point or directional
/// light can reach a point inside a smooth dielectric only through one refracted ray, so next-event
/// estimation from inside is impossible; instead a ray from the light is refracted in, and its
/// scattering vertices are joined to the camera's (bidirectional path tracing with one connection).
/// The ray is aimed at a disc through the scene's bounding sphere, perpendicular to the light: half
/// the samples uniform on the disc, half around the point where the camera ray entered the object
/// (radius ~ 1/sigma_tr), so a 30 mm object is not lit at random far from where the camera looks.
/// The pdf of the mixture is exact.
///
/// Each full path is counted once: a light subpath keeps its vertices z1, z2, ... only while every
/// edge between them had a specular event (z1 is always kept); the camera joins them along one
/// straight edge. Paths whose every scatter-to-scatter edge has a specular event (single scattering
/// among them) are not sampled here. With the manifold strategy (manifold_next_event.hpp) the
/// camera reaches a light through one refraction itself, so a subpath whose light came in that way
/// is dropped whole and only light that also reflected on its way in is joined; single scattering
/// of that reflected light stays out.
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "../scene/environment_sampling.hpp"
#include "../scene/light.hpp"
#include "dielectric_interface.hpp"
#include "path_tracer_settings.hpp"

namespace lucent::reference {

/// A light as seen from the medium: light arrives travelling along -towards (directional,
/// environment sample) or from `position` (point).
struct LightEmitter {
  enum class Kind { Directional, Point, Environment } kind;
  glm::dvec3 towards{0, 0, 1}, position{0}, power{0};  ///< power: irradiance E or intensity I
  const scene::EnvironmentLight* environment = nullptr;
  std::optional<scene::EnvironmentSampler> sampler;
  /// Camera vertices reach this light by next-event estimation straight or through one refraction
  /// (manifold_next_event.hpp): its subpaths then keep only light that also reflected on its way
  /// in.
  bool cameraReachesThroughOneRefraction = false;
};

struct LightVertex {
  glm::dvec3 position, directionIn;  ///< directionIn: how the light travelled into the vertex
  std::uint32_t medium = 0;
  HeroChannelWeight weight;  ///< emitted power / pdfs, times sigma_s at the vertex
  int order = 1;             ///< scattering events on the light side, this one included
};

struct EmissionSample {
  glm::dvec3 origin, direction, weight{0};
};

/// The disc the light's rays are aimed through, and the mixture pdf on it.
class GuidedDisc {
 public:
  GuidedDisc(const glm::dvec3& centre, const glm::dvec3& axis, double radius,
             const glm::dvec3& guide, double guideRadius)
      : mCentre(centre),
        mRadius(radius),
        mGuide(guide),
        mScale(std::max(guideRadius, 1e-9 * radius)) {
    util::orthonormalBasis(axis, mE1, mE2);
  }
  glm::dvec3 sample(util::Rng& rng) const {
    const double u = rng.uniform(), phi = 2 * optics::kPi * rng.uniform(), v = rng.uniform();
    const double r = u < 0.5 ? mRadius * std::sqrt(v) : -mScale * std::log(1 - v);
    const glm::dvec3 from = u < 0.5 ? mCentre : mGuide;
    return from + r * (std::cos(phi) * mE1 + std::sin(phi) * mE2);
  }
  double pdf(const glm::dvec3& q) const {
    const double uniform =
        glm::length(q - mCentre) <= mRadius ? 1 / (optics::kPi * mRadius * mRadius) : 0;
    const double r = std::max(glm::length(q - mGuide), 1e-12 * mRadius);
    return 0.5 * uniform + 0.5 * std::exp(-r / mScale) / (2 * optics::kPi * mScale * r);
  }

 private:
  glm::dvec3 mCentre;
  double mRadius;
  glm::dvec3 mGuide;
  double mScale;
  glm::dvec3 mE1, mE2;
};

/// A ray leaving the light towards the scene's bounding sphere (centre, radius), its weight emitted
/// power / pdf, aimed with the guide `entry` (the camera's entry point).
inline EmissionSample sampleEmission(const LightEmitter& light, const glm::dvec3& centre,
                                     double radius, const glm::dvec3& entry, double guideRadius,
                                     util::Rng& rng) {
  EmissionSample out;
  glm::dvec3 towards = light.towards, power = light.power;
  double directionPdf = 1;
  if (light.kind == LightEmitter::Kind::Environment) {
    towards = light.sampler->sample(rng.uniform(), rng.uniform(), rng.uniform(), directionPdf);
    power = light.environment->lookup(towards);
    if (!(directionPdf > 0)) return out;
  }
  if (light.kind == LightEmitter::Kind::Point) {
    const glm::dvec3 axis = glm::normalize(light.position - centre);
    const double d = glm::length(light.position - centre);
    const double discRadius =
        radius * d / std::sqrt(std::max(d * d - radius * radius, 1e-12 * d * d));
    const double along = glm::dot(entry - light.position, axis);
    const glm::dvec3 guide =
        along < 0 ? light.position +
                        (entry - light.position) * (glm::dot(centre - light.position, axis) / along)
                  : centre;
    const GuidedDisc disc(centre, axis, discRadius, guide, guideRadius);
    const glm::dvec3 q = disc.sample(rng);
    const glm::dvec3 toQ = q - light.position;
    out.direction = glm::normalize(toQ);
    out.origin = light.position +
                 std::max(0.0, d - 2 * radius) * out.direction;  // start near the scene: float hits
    const double pdfSolidAngle =
        disc.pdf(q) * glm::dot(toQ, toQ) / std::abs(glm::dot(out.direction, axis));
    if (pdfSolidAngle > 0) out.weight = power / pdfSolidAngle;
    return out;
  }
  const glm::dvec3 guide = entry - towards * glm::dot(entry - centre, towards);
  const GuidedDisc disc(centre, towards, radius, guide, guideRadius);
  const glm::dvec3 q = disc.sample(rng);
  out.origin = q + 2 * radius * towards;
  out.direction = -towards;
  const double pdfArea = disc.pdf(q);
  if (pdfArea > 0) out.weight = power / (pdfArea * directionPdf);
  return out;
}

/// Traces one light subpath and appends the vertices a camera vertex may join (see the file
/// comment). With `skipOneRefraction`, a subpath whose first scatter the light reached straight or
/// through one refraction is dropped whole: the camera's next-event estimation counts those paths.
inline void traceLightSubpath(const MediumScene& scene, const scene::RayCaster& caster,
                              const EmissionSample& emission, int hero,
                              const glm::dvec3& heroChoice, const PathTracerSettings& s,
                              util::Rng& rng, std::vector<LightVertex>& out, PathTracerStats& stats,
                              bool skipOneRefraction = false) {
  ++stats.lightSubpaths;
  if (emission.weight == glm::dvec3(0)) return;
  HeroChannelWeight w;
  w.f = emission.weight;
  w.choice = heroChoice;
  glm::dvec3 pos = emission.origin, dir = emission.direction;
  std::uint32_t medium = 0;
  int order = 0, kept = 0, refractionsIn = 0, reflectionsIn = 0;
  bool specularSinceScatter = false;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (std::uint64_t events = 0; events < s.maxEvents; ++events) {
    const auto hit = caster.intersect(pos, dir, 0, kInf);
    const Medium& m = scene.media[medium];
    if (!m.vacuum()) {
      if (!hit) {
        ++stats.leakedPaths;
        return;
      }
      double t = 0;
      if (sampleFlight(m, pos, dir, hit->t, hero, rng, w, t, stats.medium)) {
        if (order > 0 && !specularSinceScatter)
          return;  // a straight edge: the camera side joins here
        if (order == 0 && skipOneRefraction && reflectionsIn == 0 && refractionsIn <= 1) return;
        pos += t * dir;
        ++order;
        out.push_back({pos, dir, medium, w, order});
        ++stats.lightVertices;
        if (++kept >= s.maxLightVertices) return;
        const double survive =
            std::min(1.0, maxComponent(w.value()) / maxComponent(emission.weight));
        if (order > 2 && survive < 1) {  // Russian roulette relative to the emitted weight
          const double q = std::max(0.05, survive);
          if (rng.uniform() >= q) return;
          w.scale(glm::dvec3(1 / q));
        }
        dir = scatterHG(dir, m.g, rng);
        specularSinceScatter = false;
        continue;
      }
    } else if (!hit) {
      return;  // left the scene
    }
    const glm::dvec3 point = surfacePoint(scene, *hit);
    const InterfaceSides sides = interfaceSides(scene, hit->triangle, dir);
    if (sides.from != medium) ++stats.mediumMismatches;
    const InterfaceCrossing c = crossInterface(scene, point, dir, sides, s.rayEpsilon, rng, false);
    specularSinceScatter |= c.specular;
    if (order == 0 && c.specular) ++(c.medium == sides.from ? reflectionsIn : refractionsIn);
    pos = c.origin, dir = c.direction, medium = c.medium;
  }
  ++stats.truncatedPaths;
}

}  // namespace lucent::reference
