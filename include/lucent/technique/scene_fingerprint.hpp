#pragma once
/// @file scene_fingerprint.hpp
/// @brief Fingerprints of what a technique's stages read of a scene besides the geometry: its
/// lights and its material (PreparedCache keys a prepare by them, LitStages a frame's light
/// stages).
#include <cstdint>
#include <variant>

#include "../optics/materials.hpp"
#include "../scene/light.hpp"
#include "../util/fingerprint.hpp"

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

}  // namespace lucent::technique::detail
