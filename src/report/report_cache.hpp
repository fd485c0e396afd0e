#pragma once
/// @file report_cache.hpp
/// @brief The report's results, one per (technique, setting), cached on disk so that a run cut
/// short (budget, Ctrl-C) resumes where it stopped. A result is keyed by the scene's fingerprint,
/// the technique and its knobs; the fingerprint covers the lucent executable itself, so a rebuilt
/// lucent measures again.
#include <optional>
#include <string>
#include <vector>

#include <lucent/image/image.hpp>
#include <lucent/util/fingerprint.hpp>

namespace lucent::report {

/// What one run of one setting measured.
struct SettingResult {
  std::string technique;
  std::string knobs;         ///< every knob (KnobValues::summary())
  std::string changedKnobs;  ///< those that differ from the defaults
  double seconds = 0, prepareSeconds = 0, frameSeconds = 0;
  double samples = 0;
  std::string sampleUnit;
  double bytes = 0;  ///< the technique's prepared data
  std::vector<std::string> warnings;
  image::Image image;  ///< linear radiance, coverage in A
};

/// The file's bytes into `f` (InputError naming it when it cannot be read).
void addFile(util::Fingerprint& f, const std::string& path);

class ResultCache {
 public:
  /// Results live in `folder` (created if missing), under `sceneKey`.
  ResultCache(std::string folder, std::string sceneKey);
  /// The cached result of this setting, if a complete one is there.
  /// The stored result of a setting, validated like any input: nullopt (measure again) unless its
  /// image is `width` x `height` with finite pixels and its figures are finite.
  std::optional<SettingResult> load(const std::string& technique, const std::string& knobs,
                                    int width, int height) const;
  /// Stores atomically: a result is there whole or not at all.
  void store(const SettingResult& result) const;
  /// The file stem of a setting: short, unique per (scene, technique, knobs), safe in a URL.
  std::string stem(const std::string& technique, const std::string& knobs) const;

 private:
  std::string mFolder, mSceneKey;
};

}  // namespace lucent::report
