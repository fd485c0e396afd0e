#pragma once
/// @file dipole_sum.hpp
/// @brief The dipole-sum techniques: the brute-force truth (exact Rd summed over dense surface
/// samples, Chang et al. 2008 Eq. 2-3) and Jensen & Buhler's hierarchical
/// approximation of the same sum. Prepare places the samples; a frame computes their irradiance and
/// sums B at every point.
#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>
#include <string>

#include "../optics/dipole.hpp"
#include "../reference/dipole_truth.hpp"
#include "../reference/jensen_buhler.hpp"
#include "single_scattering_term.hpp"
#include "technique.hpp"
#include "validity.hpp"

namespace lucent::technique {

namespace detail {

/// Memory of one surface sample: position, normals and area (80 bytes), its lit copy for the float
/// kernel (28 bytes), its near-field entry (32 bytes, near_field.hpp).
inline constexpr double kBytesPerSample =
    3 * sizeof(glm::dvec3) + sizeof(double) + 7 * sizeof(float) + 8 * sizeof(float);

inline std::vector<KnobSpec> dipoleSumKnobs() {
  return {
      KnobSpec::real("spacing", "0", 0, 1e9, "mm",
                     "sample spacing; 0 = fraction x the smallest mean free path", Phase::Prepare),
      KnobSpec::real("fraction", "0.5", 0, kUnbounded, "",
                     "spacing as a fraction of the smallest mean free path (when spacing = 0)",
                     Phase::Prepare, true),
      KnobSpec::integer(
          "max-samples", 2000000, 1, 50000000,
          "sample budget (about " + std::to_string(int(kBytesPerSample)) +
              " bytes each); a spacing from fraction is coarsened (with a warning) to respect "
              "it, an explicit spacing above it is refused",
          Phase::Prepare),
      envStrataKnob("sample"),
      KnobSpec::choice("precision", {"float", "double"},
                       "scalar of the Rd sum (sums accumulate in double)", Phase::Frame),
      profileKnob()};
}

inline Capabilities dipoleSumCapabilities() {
  Capabilities c;
  c.precomputeScaling = "O(surface area / spacing^2) samples";
  c.dynamicMaterial =
      false;  // the converged spacing follows the material's mean free path: a new prepare
  c.frameScaling = "O(points x lit samples) Rd evaluations";
  return c;
}

/// Places the samples (prepare), and at each frame lights them and sums with `Summation`, which
/// reads its knobs from the frame's (Prepared::knobs).
template <class Summation>
class DipoleSum final : public Prepared {
 public:
  DipoleSum(const SceneDescription& scene, const KnobValues& knobs, Statistics& stats,
            Summation summation)
      : Prepared(knobs), mSummation(std::move(summation)) {
    const auto dipole = dipoleOf(scene.medium.material);
    const double mfp = dipole.minMeanFreePath();
    reference::SpacingChoice choice;
    if (knobs.real("spacing") > 0) {
      choice.spacing = knobs.real("spacing");
      choice.meanFreePath = mfp;
      // An input-sized allocation: bounded before it is made.
      const std::size_t count = reference::countSurfaceSamples(scene.mesh, choice.spacing);
      const auto budget = std::size_t(knobs.integer("max-samples"));
      if (count > budget) {
        std::ostringstream why;
        why << std::setprecision(3) << "technique '" << knobs.technique()
            << "' knob spacing=" << knobs.text("spacing") << " mm gives " << double(count)
            << " surface samples (about " << double(count) * kBytesPerSample / 1e9
            << " GB), more than max-samples=" << knobs.text("max-samples")
            << "; use a larger spacing or raise max-samples";
        throw RequestError(why.str());
      }
    } else {
      const double asked = knobs.real("fraction") * mfp;
      if (!(asked > 0) || !std::isfinite(asked))
        throw RequestError("technique '" + knobs.technique() +
                           "' knob fraction=" + knobs.text("fraction") + " gives a spacing of " +
                           valueText(asked) + " mm; use a fraction near 0.5");
      choice = reference::chooseSpacing(scene.mesh, mfp, knobs.real("fraction"),
                                        std::size_t(knobs.integer("max-samples")));
      if (choice.count > std::size_t(knobs.integer("max-samples")))  // a sample per triangle
        throw RequestError("technique '" + knobs.technique() + "': the mesh's " +
                           std::to_string(scene.mesh.triangles.size()) +
                           " triangles need a sample each, more than max-samples=" +
                           knobs.text("max-samples") + "; raise max-samples (about " +
                           numberText(double(choice.count) * kBytesPerSample / 1e9) +
                           " GB) or decimate the mesh");
    }
    if (choice.budgetLimited)
      stats.warnings.push_back("sample budget reached: spacing " + std::to_string(choice.spacing) +
                               " mm is coarser than " + knobs.text("fraction") +
                               " x the mean free path " + std::to_string(mfp) +
                               " mm; raise max-samples for a converged truth");
    mSamples = stats.timePrepare(
        "samples", [&] { return reference::buildSurfaceSamples(scene.mesh, choice.spacing); });
    stats.samples = double(mSamples.size());
    stats.sampleUnit = "surface samples";
    stats.bytes = double(mSamples.size()) * kBytesPerSample;
    stats.figures["surface_samples"] = double(mSamples.size());
    stats.figures["spacing_mm"] = choice.spacing;
    stats.figures["mean_free_path_mm"] = mfp;
    stats.figures["spacing_over_mfp"] = choice.spacing / mfp;
  }

  FrameResult frame(const SceneDescription& scene, const ShadeRequest& request,
                    Statistics& stats) override {
    FrameResult out;
    if (mKnobs.text("precision") == "double")
      out.radiosity = sum<double>(scene, request, stats, out);
    else
      out.radiosity = sum<float>(scene, request, stats, out);
    return out;
  }

 private:
  template <class T>
  std::vector<glm::dvec3> sum(const SceneDescription& scene, const ShadeRequest& request,
                              Statistics& stats, FrameResult& out) {
    const auto profile = profileOf<T>(scene.medium.material, mKnobs);
    out.exitScale = double(profile.exitScale);
    const scene::IrradianceSettings irr = irradianceSettings(scene, mKnobs);
    const auto truth = stats.timeFrame("irradiance", [&] {
      return reference::DipoleTruth<T>(mSamples, profile, scene.lights, *scene.caster, irr,
                                       scene.parallelFor, scene.stage("irradiance"));
    });
    stats.figures["lit_samples"] = double(truth.stats().litSamples);
    if (truth.tableNodes()) stats.figures["profile_table_nodes"] = double(truth.tableNodes());
    scene.checkCancelled();
    return mSummation(truth, scene, request, mKnobs, stats);
  }

  Summation mSummation;
  reference::SurfaceSamples mSamples;
};

template <class Summation>
std::unique_ptr<Prepared> makeDipoleSum(const SceneDescription& scene, const KnobValues& knobs,
                                        Statistics& stats, Summation summation) {
  return std::make_unique<DipoleSum<Summation>>(scene, knobs, stats, std::move(summation));
}

/// The dipole sums hold at any size above the diffusion limit: the near field (near_field.hpp)
/// keeps a coarse spacing right on large objects.
inline void setDipoleSumRange(Technique& t) {
  t.model = "dipole";
  t.validRange = validity::thickRange() +
                 "; no upper size (a spacing coarser than the "
                 "mean free path is integrated as a disc near each point)";
  t.validity = [](const SceneDescription& scene, const KnobValues&) {
    return validity::opticallyThick(scene.mesh, scene.medium.material);
  };
  t.quickKnobs = {{"max-samples", "20000"}, {"env-strata", "4"}};
}
}  // namespace detail

inline Technique referenceTechnique() {
  Technique t;
  t.name = "reference";
  t.summary =
      "brute-force dipole truth: exact Rd summed over dense surface samples (model truth for "
      "dipole methods)";
  t.paper =
      "Jensen, Marschner, Levoy, Hanrahan 2001, Eq. 5 (dipole); Chang et al. 2008 "
      "Eq. 2-3";
  t.knobs = detail::dipoleSumKnobs();
  t.capabilities = detail::dipoleSumCapabilities();
  t.capabilities.groundTruth = true;
  t.defaultSweep = {{"fraction", {"2", "1", "0.5", "0.25"}}};
  t.referenceKnobs = {{"fraction", "0.125"}};
  detail::setDipoleSumRange(t);
  t.prepare = [](const SceneDescription& scene, const KnobValues& knobs, Statistics& stats) {
    return detail::makeDipoleSum(
        scene, knobs, stats,
        [](const auto& truth, const SceneDescription& s, const ShadeRequest& request,
           const KnobValues&, Statistics& st) {
          st.figures["rd_evaluations"] =
              double(request.points.size()) * double(truth.stats().litSamples);
          return st.timeFrame("evaluation",
                              [&] { return radiosityAt(truth, s, request, "Rd sum"); });
        });
  };
  return withSingleScattering(std::move(t));
}

inline Technique jensenBuhlerTechnique() {
  Technique t;
  t.name = "jensen-buhler";
  t.summary =
      "Jensen & Buhler 2002: the same samples in an octree, far clusters summed as one source";
  t.paper =
      "Jensen, Buhler 2002, A Rapid Hierarchical Rendering Technique for Translucent Materials, "
      "Sec. 3";
  t.knobs = detail::dipoleSumKnobs();
  t.knobs.push_back(KnobSpec::real(
      "epsilon", "0.05", 0, kUnbounded, "",
      "error bound: a node is one source when its area / distance^2 < epsilon (0 = exact sum)"));
  t.capabilities = detail::dipoleSumCapabilities();
  t.capabilities.frameScaling = "O(points x log(lit samples)) for epsilon > 0";
  t.defaultSweep = {{"epsilon", {"1", "0.3", "0.1", "0.03"}}};
  detail::setDipoleSumRange(t);
  t.prepare = [](const SceneDescription& scene, const KnobValues& knobs, Statistics& stats) {
    return detail::makeDipoleSum(
        scene, knobs, stats,
        [](const auto& truth, const SceneDescription& s, const ShadeRequest& request,
           const KnobValues& frameKnobs, Statistics& st) {
          const double epsilon = frameKnobs.real("epsilon");
          using Truth = std::decay_t<decltype(truth)>;
          using T = std::decay_t<decltype(truth.profile().eta)>;
          static_assert(std::is_same_v<Truth, reference::DipoleTruth<T>>);
          const auto tree = st.timeFrame(
              "octree", [&] { return reference::JensenBuhlerTree<T>(truth, epsilon); });
          st.figures["octree_nodes"] = double(tree.nodeCount());
          auto b = st.timeFrame("evaluation",
                                [&] { return radiosityAt(tree, s, request, "octree sum"); });
          st.figures["rd_terms"] = double(tree.termCount());
          return b;
        });
  };
  return withSingleScattering(std::move(t));
}

}  // namespace lucent::technique
