// The planner against the measurements in the repository (data/planner, written by
// bench/calibrate_planner.py from `lucent report` runs): every calibration scene is planned from
// the other scenes' data only, and its choice is compared with what was measured on that scene.
// A term the planner drops must be one whose absence was measured to cost less than the target.
#include <doctest/doctest.h>

#include <cmath>
#include <set>
#include <string>

#include <lucent/plan/leave_one_out.hpp>

#include "technique/techniques.hpp"

namespace {
namespace lp = lucent::plan;
namespace lt = lucent::technique;

lp::Calibration stored() { return lp::readCalibration(LUCENT_SOURCE_DIR "/data/planner"); }
}  // namespace

// The criteria per case: the choice's error within 1.5x of the best measured within the
// budget, its time within the budget with 20 % slack, no worse than the all-terms default where
// that fits. "No worse" is up to one display step (plan::kErrorResolution): within a time the
// planner takes a faster setting whose image cannot look different from the most accurate one's,
// and such a setting may measure up to that much worse. The criteria do not hold in every case
// yet (docs/report/planner.md lists the misses); this guards the rates measured when the
// calibration was written (75, 72 and 18 of 19) from falling, and every case must have a choice.
TEST_CASE(
    "Planner suite: each scene planned from the others, against the best measured within "
    "its budget") {
  const lp::Calibration calibration = stored();
  std::set<std::string> scenes;
  for (const auto& m : calibration.settings) scenes.insert(m.scene);
  REQUIRE(scenes.size() >= 12);
  const auto cases = lp::leaveOneOut(lt::appRegistry(), calibration);
  REQUIRE(cases.size() >= 3 * 12);
  std::size_t errorOk = 0, timeOk = 0, defaultOk = 0, defaultFits = 0;
  for (const auto& c : cases) {
    INFO(c.scene << " at " << c.budget << ": chose " << c.chosen << " (" << c.chosenSeconds
                 << " s, error " << c.chosenError << "), best " << c.best << " (" << c.bestSeconds
                 << " s, error " << c.bestError << ")");
    REQUIRE_FALSE(c.chosen.empty());
    errorOk += c.best.empty() || c.errorRatio() <= 1.5;
    timeOk += c.timeRatio() <= 1.2;
    if (c.allTermsSeconds <= c.limits.seconds) {
      ++defaultFits;
      defaultOk += c.chosenError <= c.allTermsError + lp::kErrorResolution;
    }
  }
  const double n = double(cases.size());
  MESSAGE(errorOk << " / " << n << " within 1.5x of the best error, " << timeOk
                  << " within the budget, " << defaultOk << " / " << defaultFits
                  << " no worse than the default (within a display step)");
  CHECK(double(errorOk) / n >= 0.95);
  CHECK(double(timeOk) / n >= 0.9);
  CHECK(double(defaultOk) >= 0.9 * double(defaultFits));
}

TEST_CASE("Planner suite: a term dropped on a scene was measured to matter less than the target") {
  const lp::Calibration calibration = stored();
  const lt::Registry& registry = lt::appRegistry();
  std::set<std::string> scenes;
  for (const auto& m : calibration.settings) scenes.insert(m.scene);
  std::size_t justified = 0, unmeasured = 0;
  for (const std::string& scene : scenes) {
    const auto [on, rest] = lp::detail::split(calibration, scene);
    const lp::Plan plan =
        lp::makePlan(registry, on.front()->features, rest, {}, lp::detail::measuredFit(on));
    // What dropping transport costs: the best setting measured on the scene whose reach is just
    // what the planner asked for, against the model's truth, which has every dipole term.
    if (plan.terms.reach == lt::Reach::Global) continue;
    double leastError = INFINITY;
    for (const auto* m : on) {
      const lt::Technique* t = registry.find(m->technique);
      if (t && t->capabilities.multipleScatteringReach == plan.terms.reach)
        leastError = std::min(leastError, m->modelError);
    }
    INFO(scene << ": reach " << std::string(lt::reachName(plan.terms.reach))
               << ", measured without the rest " << leastError);
    if (std::isinf(leastError)) {  // no technique of just that reach is valid there
      ++unmeasured;
      continue;
    }
    ++justified;
    CHECK(leastError <= plan.targetError);
    if (!std::isnan(plan.terms.singleShare) && !plan.terms.singleScattering)
      CHECK(plan.terms.singleShare <= plan.targetError);
  }
  MESSAGE(justified << " scenes drop transport with a measurement of what it costs, " << unmeasured
                    << " without one");
  CHECK(justified >= 4);
  CHECK(unmeasured <= 1);
}
