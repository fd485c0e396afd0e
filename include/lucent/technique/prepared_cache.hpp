#pragma once
/// @file prepared_cache.hpp
/// @brief One technique's prepare kept across runs of a front end (the VTK filter), so that what a
/// frame can change (a frame-phase knob such as prt's `rotate`, and the light or the material where
/// the technique's capabilities say a frame takes them) re-runs only the frame.
#include <memory>
#include <string>

#include "../util/fingerprint.hpp"
#include "registry.hpp"
#include "scene_fingerprint.hpp"

namespace lucent::technique {

/// What a technique's prepare read besides the geometry: its name, its prepare-phase knobs, and
/// the material and the lights unless a frame can change them (Capabilities::dynamicMaterial,
/// dynamicLight).
inline std::string prepareKey(const Technique& t, const KnobValues& knobs,
                              const SceneDescription& scene) {
  util::Fingerprint f;
  f.add(t.name);
  for (const auto& k : t.knobs)
    if (k.invalidates == Phase::Prepare) f.add(k.name).add(knobs.text(k.name));
  if (!t.capabilities.dynamicMaterial) detail::addMaterial(f, scene.medium.material);
  if (!t.capabilities.dynamicLight)
    for (const auto& light : scene.lights) detail::addLight(f, light);
  return f.hex();
}

/// Keeps the last prepare; frame-phase knobs reach it by Prepared::retune. The caller vouches for
/// the geometry and media with a fingerprint of its own, and keeps the scene a prepare was built on
/// alive and in place while it is kept (prepared data may point into it).
class PreparedCache {
 public:
  /// As Registry::render, but reusing the kept prepare when the technique, its prepare key and
  /// `geometry` are those it was built with. The statistics of a reused prepare are its own, with
  /// no prepare time and the figure "prepare_reused" = 1.
  Rendered render(const Registry& registry, const Technique& t, const SceneDescription& scene,
                  const KnobValues& knobs, const ShadeRequest& request,
                  const std::string& geometry) {
    const std::string key = geometry + "/" + prepareKey(t, knobs, scene);
    Rendered out;
    const Stopwatch clock;
    mReused = mPrepared && key == mKey;
    if (mReused) {
      registry.check(t, scene, request);
      registry.checkRange(t, scene, knobs);
      mPrepared->retune(knobs);
      out.stats = mPrepareStats;
      out.stats.prepareSeconds.clear();
      out.stats.figures["prepare_reused"] = 1;
    } else {
      clear();
      mPrepared = registry.prepare(t, scene, knobs, request, out.stats);
      mPrepareStats = out.stats;
      mKey = key;
    }
    out.frame = Registry::frame(*mPrepared, scene, request, out.stats);
    out.seconds = clock.seconds();
    return out;
  }

  /// Whether the last render reused a kept prepare.
  bool reused() const { return mReused; }
  /// Drops the kept prepare (before its scene goes away).
  void clear() {
    mPrepared.reset();
    mKey.clear();
    mReused = false;
  }

 private:
  std::unique_ptr<Prepared> mPrepared;
  Statistics mPrepareStats;
  std::string mKey;
  bool mReused = false;
};

}  // namespace lucent::technique
