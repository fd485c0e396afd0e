/// @file lucentPassPlanner.h
/// @brief vtkLucentPass's Technique "auto" (private to Lucent::Rendering): for each actor as the
/// frame's camera sees it, the planner's choice (lucent/plan) among the techniques whose GPU twin
/// is the pass. The pixel the object covers changes with the camera, so the plan does: when the
/// profile's reach falls below a pixel (the object small on screen) the terms need no transport
/// beyond a point and diffuse-brdf's twin, which draws no samples, is the fastest choice; up close
/// the plan needs local transport and picks tsis's twin with the fewest samples that meet the
/// target error. The calibration's times are CPU times; the pass reads them only to rank settings
/// by cost, which the twins share with their techniques (the same sums, per pixel).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <lucent/plan/explain.hpp>
#include <lucent/plan/planner.hpp>
#include <lucent/plan/scene_features.hpp>
#include <lucent/technique/registry.hpp>

namespace lucent::vtkpass {
namespace lt = lucent::technique;

inline constexpr const char* kPassTwin = "vtkLucentPass";

/// What the plan reads from the frame, in the surface's millimetre frame.
struct FrameView {
  scene::PinholeCamera camera;  ///< eye and target in mm, the viewport's pixels
  double parallelPixelMm = 0;   ///< > 0: a parallel projection, one pixel is this
};

struct PassPlan {
  const lt::Technique* twin = nullptr;
  lt::KnobValues knobs;
  std::string setting;                   ///< the choice as `lucent plan` prints it
  std::vector<std::string> explanation;  ///< lucent::plan::explain's lines
};

/// Why the pass cannot run `t` with `knobs` (null: at all): no twin here, a knob the twin does not
/// take set off its default, or one beyond the twin's bound; "" when it can.
inline std::string twinUnfit(const lt::Technique& t, const lt::KnobValues* knobs) {
  if (t.capabilities.gpuTwin != kPassTwin) return std::string("it has no GPU twin in ") + kPassTwin;
  if (!knobs) return "";
  for (const auto& [name, value] : knobs->values()) {
    const auto twin =
        std::find_if(t.capabilities.gpuTwinKnobs.begin(), t.capabilities.gpuTwinKnobs.end(),
                     [&](const lt::TwinKnob& k) { return k.knob == name; });
    if (twin == t.capabilities.gpuTwinKnobs.end()) {
      if (value != t.knob(name)->defaultValue) return "its GPU twin does not take " + name;
    } else if (std::isfinite(twin->max) && knobs->real(name) > twin->max) {
      return name + " " + value + " is beyond its GPU twin's bound " + lt::numberText(twin->max);
    }
  }
  return "";
}

/// The scene's features as this frame sees the object: the pixel at the object from the camera,
/// and the pixels it covers from its area by Cauchy's formula (a convex body's mean projected
/// area is a quarter of its surface area), at most the viewport.
inline plan::SceneFeatures viewFeatures(const lt::SceneDescription& scene, const FrameView& view) {
  lt::ShadeRequest none;  // per pixel, counted below
  none.camera = &view.camera;
  plan::SceneFeatures f = plan::sceneFeatures(scene, none, &view.camera);
  if (view.parallelPixelMm > 0) f.pixelMm = view.parallelPixelMm;
  const double viewport = double(view.camera.width) * double(view.camera.height);
  f.shadedPoints =
      f.pixelMm > 0 ? std::min(viewport, 0.25 * f.areaMm2 / (f.pixelMm * f.pixelMm)) : viewport;
  return f;
}

/// The plan for one actor in this frame. `frameKnobs` are the pass's own values of the knobs that
/// size targets the whole frame shares (tsis's atlas): the chosen setting takes them. Throws
/// RequestError when no twin can serve the object, naming why each cannot.
inline PassPlan planView(const lt::Registry& registry, const lt::SceneDescription& scene,
                         const FrameView& view, const plan::Calibration& calibration,
                         const plan::Budget& budget, const lt::KnobList& frameKnobs) {
  lt::ShadeRequest request;
  request.camera = &view.camera;
  const plan::Fit base = plan::sceneFit(registry, scene, request);
  const plan::Fit fit = [&base](const lt::Technique& t, const lt::KnobValues* knobs) {
    const std::string why = twinUnfit(t, knobs);
    return why.empty() ? base(t, knobs) : why;
  };
  const plan::Plan p =
      plan::makePlan(registry, viewFeatures(scene, view), calibration, budget, fit);
  if (!p.choice) {
    std::string why;
    for (const auto& e : p.excluded) why += "; " + e;
    throw lt::RequestError(
        "Technique auto: no technique whose GPU twin is the pass can serve this "
        "object" +
        why);
  }
  PassPlan out;
  out.twin = p.choice->technique;
  lt::KnobList knobs = plan::knobPairs(p.choice->knobs);
  for (const auto& [name, value] : frameKnobs) {
    if (!out.twin->knob(name)) continue;
    knobs.erase(std::remove_if(knobs.begin(), knobs.end(),
                               [&name = name](const auto& k) { return k.first == name; }),
                knobs.end());
    knobs.emplace_back(name, value);
  }
  out.knobs = out.twin->values(knobs);
  out.setting = plan::candidateLine(*p.choice);
  out.explanation = plan::explain(p, budget);
  return out;
}

}  // namespace lucent::vtkpass
