#pragma once
/// @file methods.hpp
/// @brief The rendering techniques the CLI and the bench harness run by name. Each declares its knobs;
/// later techniques (tsis, hybrid, quadgraph, prt, pathtrace) register here.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <lucent/image/image.hpp>

#include "../cli/scene_setup.hpp"
#include "knobs.hpp"

namespace lucent::render {

struct RenderResult {
  image::Image image;
  double seconds = 0;                       ///< wall time of the whole method (setup included)
  std::map<std::string, double> figures;    ///< sample counts, spacing, per-phase times ...
  std::vector<std::string> notes;           ///< warnings a user must see (e.g. "budget-limited")
};

struct Method {
  std::string name, summary;
  std::vector<KnobSpec> knobs;
  std::function<RenderResult(const cli::Scene&, const Knobs&, bool showProgress)> run;
};

const std::vector<Method>& methods();
/// Throws InputError listing the methods when `name` is unknown.
const Method& findMethod(const std::string& name);

}  // namespace lucent::render
