#pragma once
/// @file technique.hpp
/// @brief One technique, described: name, summary, the paper and equations it implements, typed
/// knobs, capabilities, the sweep that shows what its accuracy costs, and two phases:
/// prepare(scene, knobs) builds what survives a change of light or material (samples, atlas,
/// octree, graph); a frame shades the requested points. L = Ft B / pi is applied here, once, for
/// every technique that computes radiosity B.
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "../optics/dipole.hpp"
#include "../optics/fresnel.hpp"
#include "../optics/profile.hpp"
#include "../scene/irradiance.hpp"
#include "capabilities.hpp"
#include "knob.hpp"
#include "scene.hpp"
#include "statistics.hpp"

namespace lucent::technique {

/// A frame's output, one value per requested point.
struct FrameResult {
  std::vector<glm::dvec3> radiance;   ///< leaving the surface towards the viewer
  std::vector<glm::dvec3> radiosity;  ///< B (dipole-family techniques); radiance follows from it
  /// Further per-point values (e.g. "stderr", the path tracer's standard error), each named after
  /// the OutputFile knob that asks a front end to write it.
  std::vector<std::pair<std::string, std::vector<glm::dvec3>>> extras;
  /// L = Ft B exitScale / pi: 1 for the classic dipole's convention, 1/c for the profiles whose B
  /// is the exitance that crosses the boundary (optics/profile.hpp).
  double exitScale = 1;
};

/// What prepare built, and the knobs; a frame reads both. A knob whose change invalidates only the
/// frame (Phase::Frame) is read in frame(), from mKnobs, so that retune takes new values of it
/// without a new prepare (PreparedCache; the VTK filter turning prt's environment).
class Prepared {
 public:
  explicit Prepared(KnobValues knobs = {}) : mKnobs(std::move(knobs)) {}
  virtual ~Prepared() = default;
  /// Shades the request under the scene's current lights and material; adds its phases to `stats`.
  virtual FrameResult frame(const SceneDescription& scene, const ShadeRequest& request,
                            Statistics& stats) = 0;
  /// The knobs of the frames that follow: only frame-phase knobs may differ from those it was
  /// prepared with (PreparedCache keys the prepare-phase ones).
  virtual void retune(const KnobValues& knobs) { mKnobs = knobs; }

 protected:
  KnobValues mKnobs;
};

/// Values of one knob for the bench's default sweep.
struct Sweep {
  std::string knob;
  std::vector<std::string> values;
};

using KnobList = std::vector<std::pair<std::string, std::string>>;

/// The model of the physical truth: the radiative transfer equation, every scattering order, the
/// dielectric boundary. Every technique is measured against it as well as against its own model's
/// truth.
inline constexpr const char* kPhysicalModel = "radiative transfer";

struct Technique {
  std::string name;     ///< what --method, the registry and (CamelCase) VTK properties call it
  std::string summary;  ///< one line
  std::string paper;    ///< the reference and the equations implemented
  std::string requiredLibrary;  ///< the library its adapter links (empty: header-only, every front
                                ///< end has it)
  std::vector<KnobSpec> knobs;
  Capabilities capabilities;
  std::vector<Sweep> defaultSweep;  ///< what `lucent bench` sweeps when no --sweep is given
  KnobList
      referenceKnobs;   ///< the knobs of a converged result, when this technique is the reference
  KnobList quickKnobs;  ///< the cheapest settings still worth looking at: smoke tests, the
                        ///< hard-case matrix (tests/integration/test_hard_cases.cpp)
  /// The light-transport model it approximates ("dipole", "diffusion", "radiative transfer"):
  /// techniques of one model converge to the same image, so each is measured against its model's
  /// ground truth.
  std::string model;
  std::string validRange;  ///< the scenes its approximations hold for, in words (validity.hpp)
  /// "" when the scene lies in its valid range with these knobs, else the reason and the fix;
  /// checked before any work. Empty function: valid everywhere.
  std::function<std::string(const SceneDescription&, const KnobValues&)> validity;
  std::function<std::unique_ptr<Prepared>(const SceneDescription&, const KnobValues&, Statistics&)>
      prepare;

  KnobValues values(const KnobList& given = {}) const { return KnobValues(knobs, given, name); }
  const KnobSpec* knob(const std::string& knobName) const {
    for (const auto& k : knobs)
      if (k.name == knobName) return &k;
    return nullptr;
  }
};

namespace detail {
/// Irradiance through the scene's material boundary.
inline scene::IrradianceSettings irradianceSettings(const SceneDescription& scene) {
  scene::IrradianceSettings irr;
  irr.eta = scene.medium.material.eta;
  irr.rayEpsilon = scene.rayEpsilon();
  return irr;
}

/// The env-strata knob of the techniques that integrate an environment light per `where` (a
/// sample, a texel, a node): its one spec, read by irradianceSettings below.
inline KnobSpec envStrataKnob(const std::string& where, Phase phase = Phase::Frame) {
  return KnobSpec::integer("env-strata", 16, 1, 256,
                           "environment light: strata x strata directions per " + where, phase);
}

/// The same, with the technique's env-strata knob.
inline scene::IrradianceSettings irradianceSettings(const SceneDescription& scene,
                                                    const KnobValues& knobs) {
  scene::IrradianceSettings irr = irradianceSettings(scene);
  irr.environmentStrata = int(knobs.integer("env-strata"));
  return irr;
}

inline optics::Dipole<double> dipoleOf(const optics::Material& m) {
  return optics::Dipole<double>::make(m.sigmaA, m.sigmaSPrime, m.eta);
}

/// The `profile` knob of the techniques that sum a diffusion profile; its choices are the core's
/// list of models (optics/profile.hpp). `phase`: Prepare where the profile is integrated into what
/// prepare builds (prt's transport vectors).
inline KnobSpec profileKnob(Phase phase = Phase::Frame) {
  std::vector<std::string> names;
  std::string help = "diffusion profile R(r):";
  for (const auto& info : optics::kProfileModels) {
    names.emplace_back(info.name);
    help += " " + std::string(info.name) + " = " + std::string(info.summary) + ";";
  }
  help.pop_back();
  return KnobSpec::choice("profile", names, help, phase);
}

/// The profile the knobs ask for, of the scene's material, in scalar T.
template <class T>
optics::Profile<T> profileOf(const optics::Material& m, const KnobValues& knobs) {
  return optics::Profile<T>::make(optics::profileModelNamed(knobs.text("profile")),
                                  optics::Rgb<T>(m.sigmaA), optics::Rgb<T>(m.sigmaSPrime),
                                  T(m.eta));
}

/// How a frame reads R(r) under the `rd` knob: in closed form where it is asked for and the
/// profile has one (the pole pairs), else from the profile's radial table, with a warning when
/// exact was asked for and cannot be served. The CPU tsis and its GPU twin both decide here.
struct RdLookup {
  bool closedForm = false;
  std::string warning;  ///< empty unless rd=exact fell back to the table
};
inline RdLookup rdLookupOf(const KnobValues& knobs) {
  const bool exact = knobs.pick<bool>("rd", {{"table", false}, {"exact", true}});
  const bool polePair = optics::isPolePair(optics::profileModelNamed(knobs.text("profile")));
  RdLookup out{exact && polePair, {}};
  if (exact && !polePair)
    out.warning = "rd=exact: profile " + knobs.text("profile") +
                  " has no closed-form kernel; its table is summed";
  return out;
}
}  // namespace detail

/// L(x_o, w_o) = Ft(eta, w_o) B(x_o) / pi (Chang et al. 2008 Eq. 2; Jensen et al.
/// 2001's diffuse exitance through the boundary), with the exact dielectric Fresnel term.
inline glm::dvec3 exitRadiance(const glm::dvec3& radiosity, double cosOut, double eta) {
  return radiosity * (optics::fresnelTransmittance(cosOut, eta) / optics::kPi);
}

/// Fills the radiance of a frame that computed only radiosity.
inline void completeRadiance(FrameResult& frame, const ShadeRequest& request, double eta) {
  if (!frame.radiance.empty() || frame.radiosity.empty()) return;
  frame.radiance.resize(frame.radiosity.size());
  for (std::size_t i = 0; i < frame.radiosity.size(); ++i)
    frame.radiance[i] =
        exitRadiance(frame.radiosity[i], request.points[i].cosOut, eta) * frame.exitScale;
}

/// B at every request point from a radiosity evaluator, in parallel, with progress.
template <class Radiosity>
std::vector<glm::dvec3> radiosityAt(const Radiosity& eval, const SceneDescription& scene,
                                    const ShadeRequest& request, const std::string& stage) {
  std::vector<glm::dvec3> b(request.points.size());
  const util::Progress progress = scene.stage(stage);
  std::atomic<std::size_t> done{0};
  scene.parallelFor(b.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) b[i] = eval.radiosity(request.points[i].position);
    if (progress) progress(double(done += end - begin) / double(b.size()));
  });
  return b;
}

}  // namespace lucent::technique
