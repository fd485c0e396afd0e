#pragma once
/// @file leave_one_out.hpp
/// @brief How good the planner's choices are, measured: each calibration scene is planned from
/// the other scenes' measurements only, at several budgets, and the chosen setting's time and
/// error measured on that scene are compared with the best setting measured there within the same
/// budget, and with the all-terms default (the default ground truth at its defaults).
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "planner.hpp"

namespace lucent::plan {

struct SuiteCase {
  std::string scene, budget;
  Budget limits;
  std::string chosen, best, allTerms;  ///< "technique (knobs)"; empty where none
  double chosenSeconds = NAN, chosenError = NAN;
  double bestSeconds = NAN, bestError = NAN;
  double allTermsSeconds = NAN, allTermsError = NAN;
  bool predictedToMeet = false;
  /// The chosen error over the best within the budget (1: the best), and the chosen time over the
  /// budget.
  double errorRatio() const { return chosenError / bestError; }
  double timeRatio() const { return chosenSeconds / limits.seconds; }
};

namespace detail {

/// Measured error of a setting against the physical truth, as the planner predicts it: its model
/// error with its model's floor on the scene.
inline double physicalError(const technique::Registry& registry, const SettingMeasurement& m,
                            const Calibration& c, const TermPlan& terms) {
  const technique::Technique* t = registry.find(m.technique);
  if (!t) return NAN;
  Candidate cand;
  cand.technique = t;
  predictFloor(m.features, c, terms, cand);
  return std::hypot(m.modelError, cand.floor);
}

inline std::string label(const SettingMeasurement& m) { return m.technique + " (" + m.knobs + ")"; }

/// The scene's measurements, and the calibration without them.
inline std::pair<std::vector<const SettingMeasurement*>, Calibration> split(
    const Calibration& c, const std::string& scene) {
  std::vector<const SettingMeasurement*> on;
  Calibration rest;
  rest.source = c.source + " without " + scene;
  for (const auto& f : c.floors)  // a floor measured on the held-out scene itself leaks too
    if (f.scene != scene) rest.floors.push_back(f);
  for (const auto& m : c.settings)
    if (m.scene == scene)
      on.push_back(&m);
    else
      rest.settings.push_back(m);
  return {on, rest};
}

/// Runs where the scene's own measurements ran: a setting measured there is valid there.
inline Fit measuredFit(const std::vector<const SettingMeasurement*>& on) {
  return [on](const technique::Technique& t, const technique::KnobValues* knobs) -> std::string {
    for (const SettingMeasurement* m : on)
      if (m->technique == t.name &&
          (!knobs || technique::KnobValues(t.knobs, knobPairs(m->knobs), t.name).summary() ==
                         knobs->summary()))
        return "";
    return "not measured on this scene";
  };
}

/// Time budgets at the quartiles of what the serving settings took on the scene.
inline std::vector<double> timeBudgets(const std::vector<const SettingMeasurement*>& serving) {
  std::vector<double> t;
  for (const auto* m : serving) t.push_back(m->seconds);
  std::sort(t.begin(), t.end());
  if (t.empty()) return {};
  return {t[t.size() / 4], t[t.size() / 2], t[(3 * t.size()) / 4]};
}

inline void fillCase(const technique::Registry& registry, const Calibration& all,
                     const std::vector<const SettingMeasurement*>& serving, const Plan& plan,
                     SuiteCase& out) {
  const technique::Technique& truth = registry.defaultReference();
  for (const SettingMeasurement* m : serving) {
    const double e = physicalError(registry, *m, all, plan.terms);
    if (plan.choice && m->technique == plan.choice->technique->name &&
        m->knobs == plan.choice->knobs)
      out.chosen = label(*m), out.chosenSeconds = m->seconds, out.chosenError = e;
    if (m->technique == truth.name && m->knobs == "defaults")
      out.allTerms = label(*m), out.allTermsSeconds = m->seconds, out.allTermsError = e;
    const bool within =
        m->seconds <= out.limits.seconds && (std::isnan(out.limits.error) || e <= out.limits.error);
    if (within && (out.best.empty() || e < out.bestError))
      out.best = label(*m), out.bestSeconds = m->seconds, out.bestError = e;
  }
  out.predictedToMeet = plan.meetsBudget;
}

}  // namespace detail

/// Every calibration scene at time budgets at the quartiles of its serving settings' times.
inline std::vector<SuiteCase> leaveOneOut(const technique::Registry& registry,
                                          const Calibration& calibration) {
  std::set<std::string> scenes;
  for (const auto& m : calibration.settings) scenes.insert(m.scene);
  std::vector<SuiteCase> out;
  for (const std::string& scene : scenes) {
    const auto [on, rest] = detail::split(calibration, scene);
    const Fit fit = detail::measuredFit(on);
    // The terms (and so which techniques serve) depend on the scene, not on the budget's time.
    const Plan probe = makePlan(registry, on.front()->features, rest, Budget{}, fit);
    std::vector<const SettingMeasurement*> serving;
    for (const SettingMeasurement* m : on) {
      const technique::Technique* t = registry.find(m->technique);
      if (t && detail::unfit(*t, fit, probe.terms).empty()) serving.push_back(m);
    }
    for (const double seconds : detail::timeBudgets(serving)) {
      SuiteCase c;
      c.scene = scene;
      c.limits.seconds = seconds;
      c.budget = technique::numberText(seconds) + " s";
      const Plan plan = makePlan(registry, on.front()->features, rest, c.limits, fit);
      detail::fillCase(registry, calibration, serving, plan, c);
      out.push_back(c);
    }
  }
  return out;
}

}  // namespace lucent::plan
