/// The dipole-sum methods: the brute-force truth, and Jensen-Buhler's hierarchical approximation of the
/// same sum. They share the samples and irradiance (knobs: spacing or fraction of the mean free path, the
/// sample budget, environment strata, scalar type); they differ in how B(xo) is summed.
#include <chrono>

#include <lucent/optics/dipole.hpp>
#include <lucent/reference/dipole_truth.hpp>
#include <lucent/reference/jensen_buhler.hpp>

#include "../util/progress_bar.hpp"
#include "../util/tbb_parallel.hpp"
#include "../util/error.hpp"
#include "methods.hpp"

namespace lucent::render {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

/// Builds the samples and irradiance, then renders with the evaluator `summation(truth, result)` returns.
template <class T, class Summation>
RenderResult runDipoleSum(const cli::Scene& scene, const Knobs& knobs, bool showProgress, const Summation& summation) {
  RenderResult out;
  const auto start = Clock::now();
  const auto dipole = optics::Dipole<T>::make(optics::Rgb<T>(scene.material.sigmaA),
                                              optics::Rgb<T>(scene.material.sigmaSPrime), T(scene.material.eta));
  const double mfp = double(dipole.minMeanFreePath());
  const double diag = scene.mesh.bounds().diagonal();
  reference::SpacingChoice choice;
  if (knobs.number("spacing") > 0) {
    choice.spacing = knobs.number("spacing");
    choice.meanFreePath = mfp;
  } else {
    choice = reference::chooseSpacing(scene.mesh, mfp, knobs.number("fraction"),
                                      std::size_t(knobs.number("max-samples")));
  }
  if (choice.budgetLimited)
    out.notes.push_back("sample budget reached: spacing " + std::to_string(choice.spacing) + " mm is coarser than " +
                        knobs.text("fraction") + " x the mean free path " + std::to_string(mfp) +
                        " mm; raise max-samples for a converged truth");
  const reference::SurfaceSamples samples = reference::buildSurfaceSamples(scene.mesh, choice.spacing);

  scene::IrradianceSettings irr;
  irr.eta = scene.material.eta;
  irr.rayEpsilon = 1e-5 * diag;
  irr.environmentStrata = int(knobs.number("env-strata"));
  const auto tIrr = Clock::now();
  util::ProgressBar irrBar("irradiance", showProgress);
  const reference::DipoleTruth<T> truth(samples, dipole, scene.lights, *scene.caster, irr, util::tbbFor,
                                        [&](double f) { irrBar.update(f); });
  irrBar.finish();
  out.figures["irradiance_seconds"] = since(tIrr);

  const auto tEval = Clock::now();
  const auto hits = reference::primaryHits(scene.camera, scene.mesh, scene.vertexNormals, *scene.caster, util::tbbFor);
  std::size_t covered = 0;
  for (const auto& h : hits) covered += h.has_value();
  out.figures["shaded_pixels"] = double(covered);
  const auto& evaluator = summation(truth, out);
  util::ProgressBar evalBar("Rd sum", showProgress);
  out.image = reference::renderTruth(evaluator, scene.camera, hits, util::tbbFor, [&](double f) { evalBar.update(f); });
  evalBar.finish();
  out.figures["evaluation_seconds"] = since(tEval);

  out.seconds = since(start);
  out.figures["spacing_mm"] = choice.spacing;
  out.figures["mean_free_path_mm"] = mfp;
  out.figures["spacing_over_mfp"] = choice.spacing / mfp;
  out.figures["surface_samples"] = double(truth.stats().samples);
  out.figures["lit_samples"] = double(truth.stats().litSamples);
  return out;
}

std::vector<KnobSpec> dipoleSumKnobs() {
  return {{"spacing", "0", "sample spacing in mm; 0 = fraction x the smallest mean free path"},
          {"fraction", "0.5", "spacing as a fraction of the smallest mean free path (when spacing = 0)"},
          {"max-samples", "2000000", "sample budget; the spacing is coarsened (with a warning) to respect it"},
          {"env-strata", "16", "environment light: strata x strata directions per sample"},
          {"precision", "float", "scalar of the Rd sum: float or double (sums accumulate in double)"}};
}

template <class Run>
RenderResult byPrecision(const Knobs& knobs, const std::string& method, const Run& run) {
  const std::string& p = knobs.text("precision");
  if (p == "double") return run(double{});
  if (p != "float") throw InputError("method '" + method + "' knob precision must be float or double, not '" + p + "'");
  return run(float{});
}
}  // namespace

Method referenceMethod() {
  return {"reference",
          "brute-force dipole truth: exact Rd summed over dense surface samples (model truth for dipole methods)",
          dipoleSumKnobs(), [](const cli::Scene& scene, const Knobs& knobs, bool progress) {
            return byPrecision(knobs, "reference", [&](auto scalar) {
              using T = decltype(scalar);
              return runDipoleSum<T>(scene, knobs, progress, [&](const reference::DipoleTruth<T>& truth, RenderResult& out)
                                                                 -> const reference::DipoleTruth<T>& {
                out.figures["rd_evaluations"] = out.figures["shaded_pixels"] * double(truth.stats().litSamples);
                return truth;
              });
            });
          }};
}

Method jensenBuhlerMethod() {
  std::vector<KnobSpec> knobs = dipoleSumKnobs();
  knobs.push_back({"epsilon", "0.05", "error bound: a node is one source when its area / distance^2 < epsilon (0 = exact sum)"});
  return {"jensen-buhler",
          "Jensen & Buhler 2002: the same samples in an octree, far clusters summed as one source",
          knobs, [](const cli::Scene& scene, const Knobs& knobs, bool progress) {
            const double epsilon = knobs.number("epsilon");
            if (!(epsilon >= 0)) throw InputError("method 'jensen-buhler' knob epsilon must be >= 0");
            return byPrecision(knobs, "jensen-buhler", [&](auto scalar) {
              using T = decltype(scalar);
              std::unique_ptr<reference::JensenBuhlerTree<T>> tree;
              return runDipoleSum<T>(scene, knobs, progress, [&](const reference::DipoleTruth<T>& truth, RenderResult& out)
                                                                 -> const reference::JensenBuhlerTree<T>& {
                const auto start = Clock::now();
                tree = std::make_unique<reference::JensenBuhlerTree<T>>(truth, epsilon);
                out.figures["octree_build_seconds"] = since(start);
                out.figures["octree_nodes"] = double(tree->nodeCount());
                return *tree;
              });
            });
          }};
}

}  // namespace lucent::render
