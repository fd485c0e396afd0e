#pragma once
/// @file scene_fingerprint.hpp
/// @brief Fingerprints of what a technique's stages read of a scene besides the geometry: its
/// lights, its material and the knobs (PreparedCache keys a prepare by them, LitStages a frame's
/// light stages, the GPU pass what it uploads).
#include <cstdint>
#include <variant>

#include "../optics/materials.hpp"
#include "../scene/light.hpp"
#include "../util/fingerprint.hpp"
#include "knob.hpp"

namespace lucent::technique::detail {

inline void addLight(util::Fingerprint& f, const scene::Light& light) {
  f.addValue(std::uint64_t(light.index()));
  if (const auto* p = std::get_if<scene::PointLight>(&light))
    f.addValue(p->position).addValue(p->intensity);
  else if (const auto* d = std::get_if<scene::DirectionalLight>(&light))
    f.addValue(d->towardLight).addValue(d->irradiance);
  else if (const auto* e = std::get_if<scene::EnvironmentLight>(&light))
    f.addValue(e->width).addValue(e->height).addValue(e->layout).addValue(e->scale).addArray(
        e->radiance);
}

inline void addMaterial(util::Fingerprint& f, const optics::Material& m) {
  f.add(m.name).addValue(m.eta);
  for (int c = 0; c < 3; ++c) f.addValue(m.sigmaA[c]).addValue(m.sigmaSPrime[c]);
}

/// Every knob's name and value.
inline void addKnobs(util::Fingerprint& f, const KnobValues& knobs) {
  for (const auto& spec : knobs.specs()) f.add(spec.name).add(knobs.text(spec.name));
}

}  // namespace lucent::technique::detail
