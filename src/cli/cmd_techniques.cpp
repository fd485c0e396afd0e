/// `lucent techniques [--json]`: every technique of the registry with its paper, capabilities and
/// knobs (kind, default, range or choices, unit, the phase a change invalidates, help). Read, never
/// written by hand.
#include <cstdio>
#include <iostream>

#include "../technique/techniques.hpp"
#include "args.hpp"
#include "commands.hpp"
#include "json_writer.hpp"

namespace lucent::cli {

namespace {
using technique::Capabilities;
using technique::KnobSpec;

/// (name, value) of every yes/no capability, in one order for the text and the JSON.
std::vector<std::pair<const char*, bool>> flags(const Capabilities& c) {
  return {{"point_lights", c.pointLights},
          {"directional_lights", c.directionalLights},
          {"environment_lights", c.environmentLights},
          {"heterogeneous_media", c.heterogeneousMedia},
          {"inclusions", c.inclusions},
          {"single_scattering", c.singleScattering},
          {"multiple_scattering", c.multipleScattering},
          {"dynamic_light", c.dynamicLight},
          {"dynamic_material", c.dynamicMaterial},
          {"dynamic_shape", c.dynamicShape},
          {"keeps_light_stages", c.keepsLightStages},
          {"per_pixel", c.perPixel},
          {"per_vertex", c.perVertex},
          {"needs_camera", c.needsCamera},
          {"ground_truth", c.groundTruth}};
}

std::string knobJson(const KnobSpec& k) {
  JsonObject o;
  o.add("name", k.name)
      .add("vtk_name", technique::camelCase(k.name))
      .add("kind", technique::kindName(k.kind));
  o.add("default", k.defaultValue);
  if (k.kind == technique::KnobKind::Integer || k.kind == technique::KnobKind::Real) {
    o.add("min", k.min).add("max", k.max).raw("min_exclusive", k.minExclusive ? "true" : "false");
  }
  if (k.kind == technique::KnobKind::Choice) {
    o.raw("choices", jsonStrings(k.choices));
  }
  if (!k.extension.empty()) o.add("extension", k.extension);
  return o.add("unit", k.unit)
      .add("invalidates", technique::phaseName(k.invalidates))
      .add("help", k.help)
      .str();
}

std::string techniqueJson(const technique::Technique& t) {
  JsonObject caps;
  for (const auto& [name, value] : flags(t.capabilities)) caps.raw(name, value ? "true" : "false");
  std::vector<std::string> twin;
  for (const auto& k : t.capabilities.gpuTwinKnobs)
    twin.push_back(JsonObject().add("knob", k.knob).add("max", k.max).str());
  caps.raw("gpu_twin_knobs", jsonArray(twin));
  caps.add("multiple_scattering_reach",
           technique::reachName(t.capabilities.multipleScatteringReach))
      .add("gpu_twin", t.capabilities.gpuTwin)
      .add("precompute_scaling", t.capabilities.precomputeScaling)
      .add("frame_scaling", t.capabilities.frameScaling);
  std::vector<std::string> knobs, sweep;
  for (const auto& k : t.knobs) knobs.push_back(knobJson(k));
  for (const auto& s : t.defaultSweep) {
    sweep.push_back(JsonObject().add("knob", s.knob).raw("values", jsonStrings(s.values)).str());
  }
  JsonObject o;
  o.add("name", t.name)
      .add("vtk_name", technique::camelCase(t.name))
      .add("summary", t.summary)
      .add("paper", t.paper)
      .add("required_library", t.requiredLibrary)
      .add("model", t.model)
      .add("valid_range", t.validRange);
  return o.add("capabilities", caps)
      .raw("knobs", jsonArray(knobs))
      .raw("default_sweep", jsonArray(sweep))
      .str();
}

std::string techniqueText(const technique::Technique& t) {
  std::string s = t.name + ": " + t.summary + "\n  paper: " + t.paper + "\n";
  if (!t.requiredLibrary.empty()) s += "  requires: " + t.requiredLibrary + "\n";
  if (!t.model.empty()) s += "  model: " + t.model + "\n";
  if (!t.validRange.empty()) s += "  valid for: " + t.validRange + "\n";
  s += "  can:";
  for (const auto& [name, value] : flags(t.capabilities))
    if (value) s += std::string(" ") + name;
  s += "\n  cannot:";
  for (const auto& [name, value] : flags(t.capabilities))
    if (!value) s += std::string(" ") + name;
  if (t.capabilities.multipleScattering)
    s += std::string("\n  multiple scattering reach: ") +
         technique::reachName(t.capabilities.multipleScatteringReach);
  if (!t.capabilities.gpuTwin.empty()) s += "\n  GPU twin: " + t.capabilities.gpuTwin;
  s += "\n  prepare: " + t.capabilities.precomputeScaling +
       "; frame: " + t.capabilities.frameScaling + "\n";
  for (const auto& k : t.knobs) {
    const bool ranged =
        k.kind != technique::KnobKind::Text && k.kind != technique::KnobKind::OutputFile;
    s += "    " + k.name + " (" + technique::kindName(k.kind) +
         (ranged ? " " + k.rangeText() : std::string()) + (k.unit.empty() ? "" : " " + k.unit) +
         ", default " + (k.defaultValue.empty() ? "none" : k.defaultValue) + ", invalidates " +
         technique::phaseName(k.invalidates) + "): " + k.help + "\n";
  }
  return s;
}
}  // namespace

int runTechniques(int argc, char** argv) {
  Args args("techniques", "lucent techniques [--json]",
            {{"json", "",
              "print the registry as JSON (what front ends and the ParaView XML generator read)"}});
  if (!args.parseOptionsOnly(argc, argv)) return 0;
  const auto& all = technique::appRegistry().all();
  if (args.has("json")) {
    std::vector<std::string> items;
    for (const auto& t : all) items.push_back(techniqueJson(t));
    std::cout << "{\n  \"techniques\": " << jsonArray(items) << "\n}\n";
  } else {
    for (const auto& t : all) std::cout << techniqueText(t) << "\n";
  }
  return 0;
}

}  // namespace lucent::cli
