#pragma once
/// @file hero_choice.hpp
/// @brief How often each channel is a path's hero (hero_channel_weight.hpp): P_c = 0.8 Rd_c /
/// sum Rd + 0.2 / 3 for the object medium's total diffuse reflectance Rd (Jensen et al. 2001,
/// Eq. 14), so the channels are sampled about as often as they show in the image and none less
/// than 1/15 of the time. Shared by the volumetric path tracer and the random walk.
#include <cmath>
#include <cstddef>

#include <glm/vec3.hpp>

#include "../optics/dipole.hpp"
#include "participating_media.hpp"

namespace lucent::reference {

/// The object's medium, which sets the scales of the light subpaths and the hero choice: the
/// first one that is not vacuum (nullptr if none is).
inline const Medium* firstMedium(const MediumScene& scene) {
  for (std::size_t i = 1; i < scene.media.size(); ++i)
    if (!scene.media[i].vacuum()) return &scene.media[i];
  return nullptr;
}

/// P_c as above; uniform where Rd says nothing (no medium, or a pure absorber).
inline glm::dvec3 reflectanceHeroChoice(const MediumScene& scene) {
  const Medium* m = firstMedium(scene);
  if (!m) return glm::dvec3(1.0 / 3);
  const glm::dvec3 rd =
      optics::Dipole<double>::make(m->sigmaA, (1 - m->g) * m->sigmaS, m->eta).total();
  const double sum = rd.x + rd.y + rd.z;
  if (!(sum > 0) || !std::isfinite(sum)) return glm::dvec3(1.0 / 3);
  return 0.8 * rd / sum + glm::dvec3(0.2 / 3);
}

}  // namespace lucent::reference
