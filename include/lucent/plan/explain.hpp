#pragma once
/// @file explain.hpp
/// @brief A plan in words: the scene's ratios, each term with its reason, the choice with the
/// measured figures its prediction rests on, the runners-up, what was excluded and why, and where
/// the scene lies outside the calibration data.
#include <algorithm>
#include <string>
#include <vector>

#include "planner.hpp"

namespace lucent::plan {

/// "tsis: samples=1600, atlas-resolution=1024, ...": a technique and every knob's value, as front
/// ends report the setting they ran.
inline std::string settingText(const technique::Technique& t, const technique::KnobValues& knobs) {
  std::string s = t.name + ":";
  for (const auto& [name, value] : knobs.values())
    s += (s.back() == ':' ? " " : ", ") + name + "=" + value;
  return s;
}

inline std::string candidateLine(const Candidate& c) {
  using technique::numberText;
  return c.technique->name + " (" + c.knobs + "): " + numberText(c.seconds) + " s (frame " +
         numberText(c.frameSeconds) + " s), error " + numberText(c.error) + " against the " +
         "physical truth";
}

/// Where the prediction of a candidate comes from, in one line.
inline std::string evidenceLine(const Candidate& c) {
  using technique::numberText;
  std::string s = "time t = " + numberText(std::exp(c.time.law.intercept)) + " s";
  for (std::size_t k = 0; k < kCostDriverNames.size(); ++k)
    s += isCountDriver(k)
             ? std::string(" x ") + kCostDriverNames[k] + "^" + numberText(c.time.law.slope[k])
             : std::string(" x e^(") + numberText(c.time.law.slope[k]) + " " + kCostDriverNames[k] +
                   ")";
  s += " fitted on " + std::to_string(c.scenesMeasured) +
       " calibration scenes and corrected by its misses on the nearest of them; error against "
       "its model's truth " +
       numberText(c.modelError) + " from the nearest measured scenes (" + c.errorFrom.nearestScene +
       " at distance " + numberText(c.errorFrom.nearestDistance) + ")";
  if (c.technique->model == technique::kPhysicalModel) return s + "; its model is the physical one";
  if (!c.floorFrom.nearestScene.empty())
    return s + "; the " + c.technique->model + " model's own error " + numberText(c.floor) +
           " (path tracer, nearest " + c.floorFrom.nearestScene + ")";
  return s + "; the " + c.technique->model + " model's own error not measured, taken as " +
         numberText(c.floor) + " (the single scattering it leaves out)";
}

/// "time 0.1 s, error 0.05" (the limits given).
inline std::string budgetText(const Budget& budget) {
  using technique::numberText;
  std::string s = std::isfinite(budget.seconds) ? "time " + numberText(budget.seconds) + " s" : "";
  if (!std::isnan(budget.error))
    s += (s.empty() ? "" : ", ") + ("error " + numberText(budget.error));
  return s;
}

inline std::string featuresLine(const SceneFeatures& f) {
  using technique::lengthText;
  using technique::numberText;
  return "size " + lengthText(f.sizeMm) + " = " + numberText(f.sizeInMeanFreePaths()) +
         " mean free paths; albedo " + numberText(f.albedo) + "; mean chord " +
         lengthText(f.thicknessMm) + " = " + numberText(f.thicknessInDiffusionLengths()) +
         " diffusion lengths; Rd reach " + numberText(f.reachInPixels()) + " pixels; back-lit " +
         numberText(100 * f.backLitShare) + " %; " + numberText(f.shadedPoints) + " points shaded" +
         (f.heterogeneous ? "; heterogeneous medium" : "") + (f.inclusions ? "; inclusions" : "") +
         (f.environment() ? "; environment light" : "");
}

/// The plan as lines; `alternatives` runners-up are listed after the choice.
inline std::vector<std::string> explain(const Plan& plan, const Budget& budget,
                                        std::size_t alternatives = 3) {
  using technique::numberText;
  std::vector<std::string> out{"scene: " + featuresLine(plan.features)};
  for (const auto& t : plan.terms.terms)
    out.push_back(std::string(t.simulated ? "  + " : "  - ") + t.term + ": " + t.reason);
  out.push_back("budget: " + (budget.given() ? budgetText(budget)
                                             : "none; the default target error " +
                                                   numberText(plan.targetError)));
  if (!std::isnan(plan.achievableTarget))
    out.push_back("reachable: no setting is predicted within error " +
                  numberText(plan.targetError) +
                  " here (the models' own error against the physical truth, or the truth's noise, "
                  "lies above it), so the choice is held to " +
                  numberText(plan.achievableTarget) +
                  ", the target combined with the least error predicted; accuracy no setting "
                  "shows is not paid for");
  if (!plan.choice) {
    out.push_back("choice: none: no technique is calibrated and able to serve this scene");
  } else {
    out.push_back(
        std::string(plan.meetsBudget ? "choice: " : "choice (closest, budget not met): ") +
        candidateLine(*plan.choice));
    out.push_back("  because: " + evidenceLine(*plan.choice));
    if (plan.mostAccurate)
      out.push_back("  instead of the most accurate within the time, " +
                    candidateLine(*plan.mostAccurate) + ": their images differ by at most " +
                    technique::numberText(plan.choice->modelError + plan.mostAccurate->modelError) +
                    " (the sum of their errors against the model's truth), below a display step (" +
                    technique::numberText(kErrorResolution) + ")");
    if (!plan.terms.lit)
      out.push_back("  (the cheapest: with no light every technique renders the object black)");
    if (!plan.termLeftOut.empty()) out.push_back("  note: " + plan.termLeftOut);
    if (choiceMissesSingleScattering(plan))
      out.push_back(
          "  note: the choice does not simulate single scattering, which this scene calls "
          "for; what it carries is in the predicted error (its model's own error)");
  }
  std::vector<const Candidate*> others;
  for (const auto& c : plan.candidates)
    if (!plan.choice || c.technique != plan.choice->technique || c.knobs != plan.choice->knobs)
      others.push_back(&c);
  std::sort(others.begin(), others.end(), [](const Candidate* a, const Candidate* b) {
    return a->meets != b->meets ? a->meets : a->error < b->error;
  });
  for (std::size_t i = 0; i < std::min(alternatives, others.size()); ++i)
    out.push_back("  runner-up: " + candidateLine(*others[i]) +
                  (others[i]->meets ? "" : " (outside the budget)"));
  for (const auto& e : plan.excluded) out.push_back("  not considered: " + e);
  for (const auto& o : plan.outsideCalibration)
    out.push_back("warning: outside the calibration data: " + o +
                  "; the predictions are extrapolated");
  return out;
}

}  // namespace lucent::plan
