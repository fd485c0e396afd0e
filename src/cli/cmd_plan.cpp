/// `lucent plan`: which terms a scene calls for, and the technique and knobs that render them
/// within a budget, predicted from the calibration measurements; --explain gives each decision's
/// reason and the figures it rests on. --features prints the numbers the planner compares scenes
/// by (what bench/calibrate_planner.py records for every calibration scene).
#include <cmath>
#include <cstdio>
#include <string>

#include <lucent/plan/explain.hpp>
#include <lucent/plan/leave_one_out.hpp>
#include <lucent/plan/scene_features.hpp>

#include "../technique/techniques.hpp"
#include "commands.hpp"
#include "plan_setup.hpp"
#include "scene_setup.hpp"

namespace lucent::cli {

namespace {

std::vector<OptionSpec> planCommandSpecs() {
  std::vector<OptionSpec> specs = sceneOptionSpecs();
  for (auto& s : planOptionSpecs()) specs.push_back(s);
  specs.push_back({"explain", "", "the reason for every decision, with the measured figures"});
  specs.push_back({"validate", "",
                   "plan every calibration scene from the others' data (leave one out) at three "
                   "time budgets and compare with the best setting measured there (Markdown)"});
  specs.push_back({"features", "",
                   "print the scene's features as CSV (header and one row) and stop: what the "
                   "calibration records"});
  return specs;
}

void printFeatures(const plan::SceneFeatures& f) {
  const auto values = plan::featureValues(f);
  for (std::size_t k = 0; k < values.size(); ++k)
    std::printf("%s%s", k ? "," : "", plan::kFeatureNames[k]);
  std::printf("\n");
  for (std::size_t k = 0; k < values.size(); ++k) std::printf("%s%.9g", k ? "," : "", values[k]);
  std::printf("\n");
}

void printSummary(const plan::Plan& p) {
  std::string terms;
  for (const auto& t : p.terms.terms)
    if (t.simulated) terms += (terms.empty() ? "" : "; ") + t.term;
  if (plan::choiceMissesSingleScattering(p))
    terms += " (the choice leaves single scattering out: it is in the predicted error)";
  std::printf("terms: %s\n", terms.empty() ? "none" : terms.c_str());
  if (p.choice)
    std::printf("%s: %s\n", p.meetsBudget ? "plan" : "closest plan (budget not met)",
                plan::candidateLine(*p.choice).c_str());
  else
    std::printf("plan: none (no calibrated technique can serve this scene; --explain says why)\n");
  for (const auto& o : p.outsideCalibration)
    std::printf("warning: outside the calibration data: %s\n", o.c_str());
}

std::string figure(double v) { return std::isnan(v) ? "-" : technique::numberText(v); }

/// The leave-one-out table and its summary: how often the choice is within 1.5x of the best
/// error, within the budget (20 % slack), and no worse than the all-terms default where that fits.
void printValidation(const plan::Calibration& calibration) {
  const auto cases = plan::leaveOneOut(technique::appRegistry(), calibration);
  std::printf(
      "| scene | budget | chosen | s | error | best within budget | s | error | error "
      "ratio | time / budget | default (all terms) s | error |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::size_t errorOk = 0, timeOk = 0, defaultOk = 0, defaultSeen = 0, defaultFits = 0, n = 0;
  for (const auto& c : cases) {
    std::printf("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", c.scene.c_str(),
                c.budget.c_str(), c.chosen.empty() ? "none" : c.chosen.c_str(),
                figure(c.chosenSeconds).c_str(), figure(c.chosenError).c_str(),
                c.best.empty() ? "none" : c.best.c_str(), figure(c.bestSeconds).c_str(),
                figure(c.bestError).c_str(), figure(c.errorRatio()).c_str(),
                figure(c.timeRatio()).c_str(), figure(c.allTermsSeconds).c_str(),
                figure(c.allTermsError).c_str());
    ++n;
    errorOk += c.errorRatio() <= 1.5 || c.best.empty();
    timeOk += c.timeRatio() <= 1.2;
    if (c.allTermsSeconds <= c.limits.seconds) {
      ++defaultFits;
      defaultOk += c.chosenError <= c.allTermsError;
      defaultSeen += c.chosenError <= c.allTermsError + plan::kErrorResolution;
    }
  }
  std::printf(
      "\n%zu cases: error within 1.5x of the best in %zu, time within 1.2x of the budget "
      "in %zu, no worse than the all-terms default in %zu of the %zu where it fits (%zu within a "
      "display step, %s)\n",
      n, errorOk, timeOk, defaultOk, defaultFits, defaultSeen,
      technique::numberText(plan::kErrorResolution).c_str());
}

}  // namespace

int runPlan(int argc, char** argv) {
  Args args("plan",
            "lucent plan [scene options] [--budget-ms X] [--max-error E] [--hard-limit] "
            "[--explain]",
            planCommandSpecs());
  if (!args.parseOptionsOnly(argc, argv)) return 0;
  const plan::Budget budget = budgetOf(args);
  if (args.has("validate")) {
    printValidation(calibrationOf(args));
    return 0;
  }
  Scene scene = buildScene(args);
  const technique::ShadeRequest request = technique::pixelRequest(scene.camera, scene);
  if (args.has("features")) {
    printFeatures(plan::sceneFeatures(scene, request, &scene.camera));
    return 0;
  }
  const plan::Plan p = planScene(args, scene, request, budget);
  if (args.has("explain"))
    for (const std::string& line : plan::explain(p, budget)) std::printf("%s\n", line.c_str());
  else
    printSummary(p);
  enforceHardLimit(p, budget);
  return 0;
}

}  // namespace lucent::cli
