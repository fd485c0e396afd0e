#pragma once
/// @file lit_stages.hpp
/// @brief What a frame builds from the lights, the material and the knobs (irradiance into the
/// atlas, importance samples, translucent shadow maps), kept for the next frame. A frame that
/// changes only the points, a new view, reuses it and only evaluates; a frame that changes a light,
/// the material or a knob builds it again, as Chang et al. 2008's run time redoes these stages when
/// light or material change.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "knob.hpp"
#include "scene.hpp"
#include "scene_fingerprint.hpp"
#include "statistics.hpp"

namespace lucent::technique {

/// The frame's lights, material and every knob's value, as one key.
inline std::string litKey(const SceneDescription& scene, const KnobValues& knobs) {
  util::Fingerprint f;
  for (const auto& light : scene.lights) detail::addLight(f, light);
  detail::addMaterial(f, scene.medium.material);
  detail::addKnobs(f, knobs);
  return f.hex();
}

template <class Lit>
class LitStages {
 public:
  /// The kept stages when the key matches (figure "light_stages_reused" = 1, and the figures,
  /// samples and warnings they were built with), else `build(Statistics&)`'s, timed into `stats`.
  template <class Build>
  const Lit& get(const SceneDescription& scene, const KnobValues& knobs, Statistics& stats,
                 Build&& build) {
    const std::string key = litKey(scene, knobs);
    const bool reuse = mLit && key == mKey;
    if (!reuse) {
      mLit.reset();
      mKey.clear();
      mVertexRadiosity.clear();
      mBuilt = Statistics{};
      mLit.emplace(build(mBuilt));
      mKey = key;
      for (const auto& phase : mBuilt.frameSeconds) stats.frameSeconds.push_back(phase);
    }
    for (const auto& [name, value] : mBuilt.figures) stats.figures[name] = value;
    if (mBuilt.samples > 0) stats.samples = mBuilt.samples, stats.sampleUnit = mBuilt.sampleUnit;
    stats.warnings.insert(stats.warnings.end(), mBuilt.warnings.begin(), mBuilt.warnings.end());
    stats.figures["light_stages_reused"] = reuse ? 1 : 0;
    return *mLit;
  }
  /// Radiosity at the mesh's vertices under the kept stages (eval=vertex fills it once); emptied
  /// when the stages are built again.
  std::vector<glm::dvec3>& vertexCache() { return mVertexRadiosity; }

 private:
  std::optional<Lit> mLit;
  std::string mKey;
  Statistics mBuilt;  ///< what building them reported
  std::vector<glm::dvec3> mVertexRadiosity;
};

}  // namespace lucent::technique
