#pragma once
/// @file segment_transmittance.hpp
/// @brief Transmittance along a straight segment through a MediumScene's null interfaces (an
/// interface that refracts ends it with 0): the shadow rays of next-event estimation, shared by the
/// volumetric path tracer and the random walk.
#include <cstdint>
#include <optional>

#include <glm/vec3.hpp>

#include "../scene/ray_caster.hpp"
#include "dielectric_interface.hpp"
#include "path_tracer_settings.hpp"
#include "volume_sampling.hpp"

namespace lucent::reference {

/// Where a straight segment ended: at its end, at a refracting facet, or neither known.
struct SegmentEnd {
  bool reachedEnd = false;
  std::optional<std::uint32_t> refractingFacet;
};

/// Transmittance from x along `dir` over `length` through null interfaces only (0 at a specular
/// one), ending in `endMedium` when given; `end`, when given, learns where the segment stopped.
inline glm::dvec3 segmentTransmittance(const MediumScene& scene, const scene::RayCaster& caster,
                                       double rayEpsilon, glm::dvec3 x, std::uint32_t medium,
                                       const glm::dvec3& dir, double length,
                                       std::optional<std::uint32_t> endMedium, util::Rng& rng,
                                       PathTracerStats& st, SegmentEnd* end = nullptr) {
  glm::dvec3 tr(1);
  for (int crossings = 0; crossings < 64; ++crossings) {
    const auto hit = caster.intersect(x, dir, 0, length);
    const double seg = hit ? hit->t : length;
    if (!hit && !std::isfinite(length) && !scene.media[medium].vacuum()) {
      // A medium with no surface ahead on an endless segment (towards a directional light): the
      // path leaked out through a crossing the ray caster missed; ratio tracking there would walk
      // forever where the density is zero.
      ++st.leakedPaths;
      return glm::dvec3(0);
    }
    if (!scene.media[medium].vacuum())
      tr *= transmittance(scene.media[medium], x, dir, seg, rng, st.medium);
    if (!hit) {
      if (end) end->reachedEnd = true;
      return !endMedium || *endMedium == medium ? tr : glm::dvec3(0);
    }
    if (maxComponent(tr) <= 0) return tr;
    const InterfaceSides sides = interfaceSides(scene, hit->triangle, dir);
    if (scene.media[sides.from].eta != scene.media[sides.to].eta) {
      if (end) end->refractingFacet = hit->triangle;
      return glm::dvec3(0);
    }
    x += hit->t * dir - rayEpsilon * sides.normalTowardsPath;
    length -= hit->t;
    medium = sides.to;
  }
  return glm::dvec3(0);
}

}  // namespace lucent::reference
