#pragma once
/// @file technique_run.hpp
/// @brief How the CLI's render and bench run any technique of the registry on a scene: knobs from
/// --knob pairs, output-file knobs checked before work, progress bars per stage, one frame through
/// the camera's pixels, the radiance as an image.
#include <map>
#include <string>
#include <vector>

#include <lucent/image/image.hpp>
#include <lucent/technique/registry.hpp>

#include "args.hpp"
#include "output_paths.hpp"
#include "scene_setup.hpp"

namespace lucent::cli {

struct ImageRun {
  image::Image image;  ///< radiance in RGB, coverage in A
  technique::Statistics stats;
  std::map<std::string, double> figures;  ///< stats.flat() plus the pixels shaded
  std::vector<std::pair<std::string, image::Image>>
      extras;  ///< per-pixel extras (e.g. stderr), by name
  double seconds = 0;
};

/// "NAME=VALUE[,NAME=VALUE...]" from every occurrence of `option`, in order.
technique::KnobList knobArgs(const Args& args, const std::string& option);

/// The technique --option names, else the registry's default reference (its ground truth).
const technique::Technique& techniqueArg(const technique::Registry& registry, const Args& args,
                                         const std::string& option);

/// The product of the sweeps, each setting combined with the fixed knobs and validated.
std::vector<technique::KnobValues> sweepSettings(const technique::Technique& t,
                                                 const technique::KnobList& fixed,
                                                 const std::vector<technique::Sweep>& sweeps);

/// The technique's output-file knobs that are set, as outputs for checkOutputs (once per path).
std::vector<NamedOutput> knobOutputs(const std::vector<technique::KnobValues>& settings);

/// Prepare and one frame of `technique` on every pixel the camera sees (`pixels`: those already
/// found, else found here), with progress bars unless quiet; output-file knobs get their extras
/// written.
ImageRun renderImage(const technique::Registry& registry, const technique::Technique& technique,
                     Scene& scene, const technique::KnobValues& knobs, bool progress,
                     const technique::ShadeRequest* pixels = nullptr);

}  // namespace lucent::cli
