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

/// What one pixel covers at the object's centre, mm (0: the eye at the centre).
inline double pixelAtObjectMm(const FrameView& view) {
  return view.parallelPixelMm > 0 ? view.parallelPixelMm
                                  : plan::pixelFootprint(view.camera, glm::dvec3(0));
}

/// What a plan for this view depends on beyond the object, material and light: the pixel at the
/// object in steps of 5 %, and the side of the object the camera looks from (the light's share
/// from behind decides global transport). Cheap, so a frame whose plan holds costs no features.
inline std::string viewKey(const FrameView& view, const glm::dvec3& towardLight) {
  const double pixel = pixelAtObjectMm(view);
  const long bin = pixel > 0 && std::isfinite(pixel) ? std::lround(20 * std::log(pixel)) : 0;
  return std::to_string(bin) + (glm::dot(view.camera.eye, towardLight) < 0 ? " behind" : " front");
}

struct PassPlan {
  const lt::Technique* twin = nullptr;
  lt::KnobValues knobs;
  std::string setting;                   ///< the technique and every knob (plan::settingText)
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
  f.pixelMm = pixelAtObjectMm(view);
  const double viewport = double(view.camera.width) * double(view.camera.height);
  f.shadedPoints =
      f.pixelMm > 0 ? std::min(viewport, 0.25 * f.areaMm2 / (f.pixelMm * f.pixelMm)) : viewport;
  return f;
}

/// `knobs` with the frame's own values of the knobs it has among `frameKnobs`.
inline lt::KnobValues withFrameKnobs(const lt::Technique& t, const lt::KnobList& knobs,
                                     const lt::KnobList& frameKnobs) {
  lt::KnobList merged = knobs;
  for (const auto& [name, value] : frameKnobs) {
    if (!t.knob(name)) continue;
    merged.erase(std::remove_if(merged.begin(), merged.end(),
                                [&name = name](const auto& k) { return k.first == name; }),
                 merged.end());
    merged.emplace_back(name, value);
  }
  return t.values(merged);
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
  // Each setting is checked as the pass would draw it: with the frame's own knobs.
  const plan::Fit fit = [&](const lt::Technique& t, const lt::KnobValues* knobs) {
    if (!knobs) {
      const std::string why = twinUnfit(t, nullptr);
      return why.empty() ? base(t, nullptr) : why;
    }
    const lt::KnobValues drawn = withFrameKnobs(t, knobs->values(), frameKnobs);
    const std::string why = twinUnfit(t, &drawn);
    return why.empty() ? base(t, &drawn) : why;
  };
  const plan::Plan p =
      plan::makePlan(registry, viewFeatures(scene, view), calibration, budget, fit);
  if (!p.choice)
    throw lt::RequestError(
        "Technique auto: no technique whose GPU twin is the pass can serve this object" +
        plan::exclusionText(p));
  PassPlan out;
  out.twin = p.choice->technique;
  out.knobs = withFrameKnobs(*out.twin, plan::knobPairs(p.choice->knobs), frameKnobs);
  out.setting = plan::settingText(*out.twin, out.knobs);
  out.explanation = plan::explain(p, budget);
  return out;
}

}  // namespace lucent::vtkpass
