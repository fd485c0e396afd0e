#include "plan_setup.hpp"

#include <lucent/plan/explain.hpp>
#include <lucent/plan/scene_features.hpp>

#include "../technique/techniques.hpp"
#include "../util/error.hpp"

namespace lucent::cli {

std::vector<OptionSpec> planOptionSpecs() {
  return {
      {"budget-ms", "X", "time for prepare + one frame, milliseconds"},
      {"max-error", "E",
       "target error: relative RMS against the physical truth (default " +
           technique::numberText(plan::kDefaultTargetError) + " when no budget is given)"},
      {"hard-limit", "", "a budget no plan meets is an error (exit 2) instead of the closest plan"},
      {"calibration", "DIR",
       "the planner's measured data (settings.csv, model-floors.csv); default "
       "$LUCENT_DATA_DIR/planner or the source tree's data/planner"},
  };
}

plan::Budget budgetOf(const Args& args) {
  plan::Budget b;
  if (args.has("budget-ms")) b.seconds = args.number("budget-ms", 0, 1e-3, 1e9) / 1000;
  if (args.has("max-error")) b.error = args.number("max-error", 0, 1e-6, 1e3);
  b.hard = args.has("hard-limit");
  if (b.hard && !b.given())
    args.fail("--hard-limit needs a limit: give --budget-ms X or --max-error E");
  return b;
}

plan::Calibration calibrationOf(const Args& args) {
  const std::string dir =
      plan::calibrationDirectory(args.get("calibration"), LUCENT_SOURCE_DATA_DIR);
  try {
    return plan::readCalibration(dir);
  } catch (const plan::CalibrationError& e) {
    throw InputError(std::string("lucent ") + args.command() + ": " + e.what() +
                     " (or point --calibration at a folder holding it)");
  }
}

plan::Plan planScene(const Args& args, const Scene& scene, const technique::ShadeRequest& request,
                     const plan::Budget& budget) {
  const plan::Calibration calibration = calibrationOf(args);
  const plan::SceneFeatures features = plan::sceneFeatures(scene, request, &scene.camera);
  return plan::makePlan(technique::appRegistry(), scene, request, features, calibration, budget);
}

void enforceHardLimit(const plan::Plan& plan, const plan::Budget& budget) {
  if (!budget.hard || plan.meetsBudget) return;
  throw InputError("no technique meets the budget (" + plan::budgetText(budget) + "); closest: " +
                   (plan.choice ? plan::candidateLine(*plan.choice) : std::string("none")) +
                   "; raise the budget or drop --hard-limit");
}

}  // namespace lucent::cli
