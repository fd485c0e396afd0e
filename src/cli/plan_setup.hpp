#pragma once
/// @file plan_setup.hpp
/// @brief What `lucent plan` and `lucent render --method auto` share: the budget options, the
/// calibration folder, and the plan of a scene built from the command line.
#include <string>
#include <vector>

#include <lucent/plan/planner.hpp>

#include "args.hpp"
#include "scene_setup.hpp"

namespace lucent::cli {

/// --budget-ms, --max-error, --hard-limit, --calibration.
std::vector<OptionSpec> planOptionSpecs();

plan::Budget budgetOf(const Args& args);

/// --calibration DIR, else $LUCENT_DATA_DIR/planner, else the source tree's data/planner; a file
/// that cannot be read is bad input (InputError naming it and the command that regenerates it).
plan::Calibration calibrationOf(const Args& args);

/// The plan of the scene at the camera's pixels.
plan::Plan planScene(const Args& args, const Scene& scene, const technique::ShadeRequest& request,
                     const plan::Budget& budget);

/// When the budget is a hard limit that the plan does not meet: InputError with the closest
/// setting.
void enforceHardLimit(const plan::Plan& plan, const plan::Budget& budget);

}  // namespace lucent::cli
