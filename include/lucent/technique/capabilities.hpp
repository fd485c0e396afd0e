#pragma once
/// @file capabilities.hpp
/// @brief What a technique can do, declared with it, and what a scene and request call for: the
/// planner reads the first, and a mismatch is reported before any work, naming the techniques that
/// can.
#include <limits>
#include <string>
#include <vector>

namespace lucent::technique {

/// How far a technique's multiple scattering carries light across the surface: not at all (a
/// diffuse BRDF: right when Rd's reach is below a pixel), within the neighbourhood of the lit side
/// that a light-space map sees (local: no light crosses to a face the light does not see), or
/// everywhere (global).
enum class Reach { Point, Local, Global };

inline const char* reachName(Reach r) {
  return r == Reach::Point ? "point" : r == Reach::Local ? "local" : "global";
}

/// A knob a GPU twin shares with its technique: same name, default and lower bound; `max` is the
/// twin's own upper bound where the hardware needs a lower one (a per-pixel loop, a texture's
/// size).
struct TwinKnob {
  std::string knob;
  double max = std::numeric_limits<double>::infinity();
};

struct Capabilities {
  ///@{ Light kinds it takes.
  bool pointLights = true;
  bool directionalLights = true;
  bool environmentLights = true;
  ///@}
  ///@{ Media: a density field scaling sigma, nested bodies of other materials (inclusions).
  bool heterogeneousMedia = false;
  bool inclusions = false;
  ///@}
  ///@{ Scattering orders it simulates.
  bool singleScattering = false;
  bool multipleScattering = true;
  Reach multipleScatteringReach = Reach::Global;
  ///@}
  ///@{ What a frame can change without a new prepare.
  bool dynamicLight = true;
  bool dynamicMaterial = true;
  bool dynamicShape = false;
  /// A frame keeps what it built from the lights, material and knobs (lit_stages.hpp), so a view
  /// change only evaluates.
  bool keepsLightStages = false;
  ///@}
  ///@{ Where it produces radiance: any surface point (per pixel), mesh vertices, or only along
  /// camera rays.
  bool perPixel = true;
  bool perVertex = true;
  bool needsCamera = false;
  ///@}
  bool groundTruth = false;            ///< a reference other techniques are measured against
  std::string gpuTwin;                 ///< the GPU implementation of the same technique, if any
  std::vector<TwinKnob> gpuTwinKnobs;  ///< the knobs the GPU twin takes (same names and defaults)
  std::string precomputeScaling;  ///< how prepare's cost grows, e.g. "O(A / spacing^2) samples"
  std::string frameScaling;       ///< how a frame's cost grows
};

/// What one scene and request call for.
struct Requirements {
  bool pointLight = false, directionalLight = false, environmentLight = false;
  bool heterogeneousMedium = false, inclusions = false;
  bool perVertex = false, camera = false;
};

/// Each requirement the capabilities miss, as a phrase ("an environment light").
inline std::vector<std::string> unmet(const Capabilities& c, const Requirements& r) {
  std::vector<std::string> out;
  if (r.pointLight && !c.pointLights) out.push_back("a point light");
  if (r.directionalLight && !c.directionalLights) out.push_back("a directional light");
  if (r.environmentLight && !c.environmentLights) out.push_back("an environment light");
  if (r.heterogeneousMedium && !c.heterogeneousMedia)
    out.push_back("a heterogeneous medium (density field)");
  if (r.inclusions && !c.inclusions) out.push_back("an inclusion of another material");
  if (r.perVertex && !c.perVertex) out.push_back("per-vertex output");
  if (!r.camera && c.needsCamera) out.push_back("shading without a camera");
  return out;
}

}  // namespace lucent::technique
