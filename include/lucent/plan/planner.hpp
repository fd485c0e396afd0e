#pragma once
/// @file planner.hpp
/// @brief The effect planner: from a scene's features, the calibration measurements and a budget
/// (time, target error, or both), the terms to simulate (terms.hpp) and the technique and knobs
/// that serve them, with the predicted time and error and one line of reason per decision. It
/// reads techniques, knobs and capabilities from the registry and numbers from the calibration
/// files; it names no technique.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "../technique/registry.hpp"
#include "calibration.hpp"
#include "prediction.hpp"
#include "terms.hpp"

namespace lucent::plan {

struct Budget {
  double seconds = INFINITY;  ///< prepare + one frame
  double error = NAN;         ///< relative RMS against the physical truth; NaN: none given
  bool hard = false;          ///< a limit no plan may break (the CLI exits 2)
  bool given() const { return std::isfinite(seconds) || !std::isnan(error); }
};

/// The target error when the user gives only a time or nothing: where a term is worth simulating.
/// 5 % relative RMS is about the smallest difference a viewer sees side by side in a tone-mapped
/// image (the papers' RMSE figures sit between 0.01 and 0.05).
inline constexpr double kDefaultTargetError = 0.05;

/// Images closer than this (relative RMS) look the same: 1 % of the signal is about one step of an
/// 8-bit display in the mid-tones (1/255 of full scale, after the x / (1 + x) tone map and sRGB
/// encoding, near display value 0.5).
inline constexpr double kErrorResolution = 0.01;

/// The relative RMS error of a black image (|0 - L| / |L| = 1): a setting predicted above it is
/// worse than drawing nothing.
inline constexpr double kBlackImageError = 1.0;

/// What every front end takes in place of a technique's name to have the planner choose
/// (`render --method auto`, the VTK filter's and the pass's Technique).
inline constexpr const char* kAutomatic = "auto";

/// One technique setting, predicted on the scene.
struct Candidate {
  const technique::Technique* technique = nullptr;
  std::string knobs;  ///< as stored: changed knobs, "a=1;b=2" or "defaults"
  double seconds = NAN, frameSeconds = NAN;
  double modelError = NAN;  ///< against its model's truth
  double floor = NAN;       ///< its model's own error against the physical truth
  double error = NAN;       ///< against the physical truth: sqrt(modelError^2 + floor^2)
  Neighbours errorFrom, floorFrom;
  TimeModel time;
  std::size_t scenesMeasured = 0;
  bool meets = false;
};

/// Why a technique (with `knobs`, or at all when null) cannot run on the scene; "" when it can.
using Fit = std::function<std::string(const technique::Technique&, const technique::KnobValues*)>;

struct Plan {
  SceneFeatures features;
  TermPlan terms;
  double targetError = kDefaultTargetError;
  std::vector<Candidate> candidates;
  std::optional<Candidate> choice;
  bool meetsBudget = false;
  /// When no setting reaches the target error: the target the choice was held to instead,
  /// hypot(target, the least predicted error); NaN otherwise.
  double achievableTarget = NAN;
  /// Within a time: the most accurate setting, when a faster one whose image cannot look
  /// different from its was chosen instead (detail::mostAccurateWithin).
  std::optional<Candidate> mostAccurate;
  std::vector<std::string> excluded;            ///< "technique: why"
  /// When no technique able to take the scene simulates every term it calls for: why the choice
  /// came from those that take it, leaving a term out (e.g. a scan's heterogeneous medium shaded
  /// at vertices: only single-scattering techniques take it); empty otherwise.
  std::string termLeftOut;
  std::vector<std::string> outsideCalibration;  ///< features outside what was measured
};

namespace detail {

inline bool reaches(technique::Reach has, technique::Reach needs) { return int(has) >= int(needs); }

/// Why the technique cannot serve the terms, or the scene as `fit` says ("" when it can).
inline std::string unfit(const technique::Technique& t, const Fit& fit, const TermPlan& terms) {
  const std::string why = fit(t, nullptr);
  if (!why.empty()) return why;
  if (!t.capabilities.multipleScattering && terms.lit)
    return "it simulates no multiple scattering, the dominant term";
  if (!reaches(t.capabilities.multipleScatteringReach, terms.reach))
    return std::string("its multiple scattering is ") +
           technique::reachName(t.capabilities.multipleScatteringReach) + "; the scene needs " +
           technique::reachName(terms.reach) + " transport";
  return "";
}

/// The error floor of a technique's model on the scene: measured where the model was measured,
/// else at least the single scattering it leaves out.
inline void predictFloor(const SceneFeatures& f, const Calibration& c, const TermPlan& terms,
                         Candidate& cand) {
  const technique::Technique& t = *cand.technique;
  if (t.model == technique::kPhysicalModel) {
    cand.floor = 0;
    return;
  }
  std::vector<const ModelFloor*> rows;
  for (const auto& r : c.floors)
    if (r.model == t.model) rows.push_back(&r);
  cand.floorFrom = predictFromNeighbours(f, rows, [](const ModelFloor& r) { return r.error; });
  cand.floor = !std::isnan(cand.floorFrom.value) ? cand.floorFrom.value
               : (!t.capabilities.singleScattering && !std::isnan(terms.singleShare))
                   ? terms.singleShare
                   : 0;
}

/// Every calibrated setting of `t` valid on the scene, predicted.
inline std::vector<Candidate> settingsOf(const technique::Technique& t, const SceneFeatures& f,
                                         const Fit& fit, const Calibration& c,
                                         const TermPlan& terms) {
  std::map<std::string, std::vector<const SettingMeasurement*>> byKnobs;
  for (const auto& m : c.settings)
    if (m.technique == t.name) byKnobs[m.knobs].push_back(&m);
  std::vector<Candidate> out;
  for (const auto& [knobs, rows] : byKnobs) {
    try {
      const technique::KnobValues values = t.values(knobPairs(knobs));
      if (!fit(t, &values).empty()) continue;  // a setting the scene rules out
    } catch (const std::exception&) {
      continue;  // a knob or value this build no longer has
    }
    Candidate cand;
    cand.technique = &t, cand.knobs = knobs, cand.scenesMeasured = rows.size();
    cand.time = fitTimeModel(rows, [](const SettingMeasurement& m) { return m.seconds; });
    cand.seconds = cand.time(f);
    cand.frameSeconds =
        fitTimeModel(rows, [](const SettingMeasurement& m) { return m.frameSeconds; })(f);
    cand.errorFrom =
        predictFromNeighbours(f, rows, [](const SettingMeasurement& m) { return m.modelError; });
    cand.modelError = cand.errorFrom.value;
    predictFloor(f, c, terms, cand);
    cand.error = std::hypot(cand.modelError, cand.floor);
    out.push_back(std::move(cand));
  }
  return out;
}

/// Why none of the technique's calibrated settings is a candidate: none measured, or each out of
/// its valid range here (the first one's reason).
inline std::string whyNoSetting(const technique::Technique& t, const Fit& fit,
                                const Calibration& c) {
  for (const auto& m : c.settings) {
    if (m.technique != t.name) continue;
    try {
      const technique::KnobValues values = t.values(knobPairs(m.knobs));
      const std::string why = fit(t, &values);
      if (!why.empty()) return "its calibrated settings are out of range here: " + why;
    } catch (const std::exception& e) {
      return std::string("its calibrated knobs do not apply to this build (") + e.what() + "); " +
             kRecalibrate;
    }
  }
  return std::string(
             "not calibrated (its model has no truth to measure it against, or it was "
             "added since); ") +
         kRecalibrate;
}

/// The features of the scene that lie outside the span of the calibration scenes (by more than a
/// tenth of the similarity scale), each as "name value (measured lo..hi)".
/// The least and greatest of each coordinate over the calibration's rows, each row's coordinates
/// computed once.
template <std::size_t N, class Coordinates>
std::pair<std::array<double, N>, std::array<double, N>> spanOf(const Calibration& c,
                                                               const Coordinates& coordinates) {
  std::array<double, N> lo, hi;
  lo.fill(INFINITY), hi.fill(-INFINITY);
  for (const auto& m : c.settings) {
    const std::array<double, N> v = coordinates(m.features);
    for (std::size_t k = 0; k < N; ++k)
      lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
  }
  return {lo, hi};
}

inline std::vector<std::string> outsideOf(const SceneFeatures& f, const Calibration& c) {
  std::vector<std::string> out;
  if (c.settings.empty()) return out;
  const auto x = similarityCoordinates(f);
  const auto [lo, hi] = spanOf<x.size()>(c, similarityCoordinates);
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double margin = 0.1 * kSimilarityScale[k];
    if (x[k] < lo[k] - margin || x[k] > hi[k] + margin)
      out.push_back(std::string(kSimilarityNames[k]) + " " + technique::numberText(x[k]) +
                    (isLogCoordinate(k) ? " (log10)" : "") + ", measured " +
                    technique::numberText(lo[k]) + " to " + technique::numberText(hi[k]));
  }
  const auto d = costDrivers(f);  // times extrapolated past a factor 2 in a count
  const auto [dlo, dhi] = spanOf<kCostDrivers>(c, costDrivers);
  for (std::size_t k = 0; k < d.size(); ++k)
    if (isCountDriver(k) && (d[k] < dlo[k] - std::log(2.0) || d[k] > dhi[k] + std::log(2.0)))
      out.push_back(std::string(kCostDriverNames[k]) + " " + technique::numberText(std::exp(d[k])) +
                    ", measured " + technique::numberText(std::exp(dlo[k])) + " to " +
                    technique::numberText(std::exp(dhi[k])) + " (times extrapolated)");
  return out;
}

inline bool within(const Candidate& c, double seconds, double error) {
  return c.seconds <= seconds && !(c.error > error);
}

/// The candidate `better` prefers among those within both limits (null: none).
template <class Better>
const Candidate* bestWithin(const std::vector<Candidate>& candidates, double seconds, double error,
                            const Better& better) {
  const Candidate* best = nullptr;
  for (const Candidate& c : candidates)
    if (within(c, seconds, error) && (!best || better(c, *best))) best = &c;
  return best;
}

/// The most accurate candidate within `seconds` and `error`, or a faster one whose image cannot
/// differ from it by a display step: two settings of one model differ from each other by at most
/// the sum of their errors against that model's truth (the triangle inequality), so when that sum
/// is below kErrorResolution no one sees which was drawn. `mostAccurate` gets the most accurate.
inline const Candidate* mostAccurateWithin(const std::vector<Candidate>& candidates, double seconds,
                                           double error, const Candidate** mostAccurate) {
  const Candidate* best = bestWithin(
      candidates, seconds, error, [](const auto& a, const auto& b) { return a.error < b.error; });
  *mostAccurate = best;
  if (!best) return nullptr;
  const Candidate* fastest = best;
  for (const Candidate& c : candidates)
    if (within(c, seconds, error) && c.technique->model == best->technique->model &&
        c.modelError + best->modelError <= kErrorResolution && c.seconds < fastest->seconds)
      fastest = &c;
  return fastest;
}

/// The candidates to choose from: those predicted better than a black image (relative RMS error
/// kBlackImageError), unless none is.
inline std::vector<Candidate> betterThanBlack(const std::vector<Candidate>& candidates) {
  std::vector<Candidate> out;
  for (const Candidate& c : candidates)
    if (c.error < kBlackImageError) out.push_back(c);
  return out.empty() ? candidates : out;
}

/// Picks among the candidates: with a target error, the fastest that meets both limits; with only
/// a time, the most accurate within it (or a faster setting whose image cannot look different).
/// When no setting reaches the target error (the model's own error, or a truth's noise, lies above
/// it), the target is what the most accurate setting reaches, hypot(target, least error): paying
/// for accuracy that no setting shows buys nothing. None meeting the time: the fastest within the
/// target, else the fastest. A setting predicted worse than a black image is never chosen while
/// another exists.
inline void choose(const Budget& budget, Plan& plan) {
  const auto faster = [](const Candidate& a, const Candidate& b) { return a.seconds < b.seconds; };
  const std::vector<Candidate> pool = betterThanBlack(plan.candidates);
  const bool errorAsked = !std::isnan(budget.error);
  const double target = errorAsked ? budget.error : INFINITY;
  const Candidate* mostAccurate = nullptr;
  const Candidate* best = errorAsked
                              ? bestWithin(pool, budget.seconds, target, faster)
                              : mostAccurateWithin(pool, budget.seconds, target, &mostAccurate);
  if (best && mostAccurate && best != mostAccurate) plan.mostAccurate = *mostAccurate;
  plan.meetsBudget = best != nullptr;
  double leastError = INFINITY;
  for (const Candidate& c : pool) leastError = std::min(leastError, c.error);
  if (!best && errorAsked && leastError > target && std::isfinite(leastError)) {
    plan.achievableTarget = std::hypot(target, leastError);
    best = bestWithin(pool, budget.seconds, plan.achievableTarget, faster);
    if (!best) best = bestWithin(pool, INFINITY, plan.achievableTarget, faster);
  }
  if (!best && errorAsked) best = bestWithin(pool, INFINITY, target, faster);
  if (!best) best = bestWithin(pool, INFINITY, INFINITY, faster);
  for (Candidate& c : plan.candidates)  // `meets` says: within the user's own limits
    c.meets = within(c, budget.seconds, target);
  if (best) plan.choice = *best;
}

}  // namespace detail

namespace detail {
/// Every calibrated setting of every technique that serves `terms` into plan.candidates; the
/// others, with why, into plan.excluded.
inline void gatherCandidates(const technique::Registry& registry, const SceneFeatures& features,
                             const Calibration& calibration, const Fit& fit, const TermPlan& terms,
                             Plan& plan) {
  for (const technique::Technique& t : registry.all()) {
    const std::string why = unfit(t, fit, terms);
    if (!why.empty()) {
      plan.excluded.push_back(t.name + ": " + why);
      continue;
    }
    std::vector<Candidate> settings = settingsOf(t, features, fit, calibration, terms);
    if (settings.empty())
      plan.excluded.push_back(t.name + ": " + whyNoSetting(t, fit, calibration));
    for (auto& s : settings) plan.candidates.push_back(std::move(s));
  }
}
}  // namespace detail

/// The plan for a scene with these features; `fit` says where a technique or setting cannot run.
inline Plan makePlan(const technique::Registry& registry, const SceneFeatures& features,
                     const Calibration& calibration, const Budget& budget, const Fit& fit) {
  Plan plan;
  plan.features = features;
  plan.targetError = std::isnan(budget.error) ? kDefaultTargetError : budget.error;
  Budget limits = budget;  // no limit at all: the fastest setting within the default target
  if (!budget.given()) limits.error = kDefaultTargetError;
  plan.terms = decideTerms(features, calibration, plan.targetError);
  plan.outsideCalibration = detail::outsideOf(features, calibration);
  detail::gatherCandidates(registry, features, calibration, fit, plan.terms, plan);
  if (plan.candidates.empty() && plan.terms.lit) {
    // Nothing that takes the scene carries every term: render with what takes it, and say so,
    // rather than render nothing (the predicted error carries what is left out).
    TermPlan takesScene = plan.terms;
    takesScene.lit = false, takesScene.reach = technique::Reach::Point;
    Plan relaxed;
    detail::gatherCandidates(registry, features, calibration, fit, takesScene, relaxed);
    if (!relaxed.candidates.empty()) {
      plan.excluded = std::move(relaxed.excluded);  // what cannot even take the scene
      plan.candidates = std::move(relaxed.candidates);
      plan.termLeftOut =
          "no technique that takes this scene simulates its multiple scattering at the reach it "
          "needs; the choice is the best of those that take it, and leaves that out";
    } else {
      // Why those that take the scene have no setting either (the first pass named the rest).
      for (auto& e : relaxed.excluded)
        if (std::find(plan.excluded.begin(), plan.excluded.end(), e) == plan.excluded.end())
          plan.excluded.push_back("(leaving a term out) " + e);
    }
  }
  if (plan.terms.lit) {
    detail::choose(limits, plan);
  } else if (const Candidate* fastest = detail::bestWithin(
                 plan.candidates, INFINITY, INFINITY,
                 [](const Candidate& a, const Candidate& b) { return a.seconds < b.seconds; })) {
    plan.choice = *fastest;  // every technique renders the unlit object black: the cheapest
    plan.meetsBudget = fastest->seconds <= budget.seconds;
    for (Candidate& c : plan.candidates) c.meets = true;  // any of them renders the same black
  }
  if (!budget.given()) plan.meetsBudget = plan.choice.has_value();  // the default is no limit
  return plan;
}

/// Where the registry's capability and range checks let a technique (and its knobs) run on a
/// scene shaded at `request`.
inline Fit sceneFit(const technique::Registry& registry, const technique::SceneDescription& scene,
                    const technique::ShadeRequest& request) {
  return [&registry, &scene, &request](const technique::Technique& t,
                                       const technique::KnobValues* knobs) -> std::string {
    try {
      if (knobs)
        registry.checkRange(t, scene, *knobs);
      else
        registry.check(t, scene, request);
    } catch (const technique::RequestError& e) {
      return e.what();
    }
    return "";
  };
}

/// "; technique: why" for every technique the plan left out: why there is no choice.
inline std::string exclusionText(const Plan& plan) {
  std::string why;
  for (const auto& e : plan.excluded) why += "; " + e;
  return why;
}

/// Whether the terms call for single scattering and the chosen technique leaves it out.
inline bool choiceMissesSingleScattering(const Plan& plan) {
  return plan.choice && plan.terms.singleScattering &&
         !plan.choice->technique->capabilities.singleScattering;
}

/// The plan for a scene shaded at `request`.
inline Plan makePlan(const technique::Registry& registry, const technique::SceneDescription& scene,
                     const technique::ShadeRequest& request, const SceneFeatures& features,
                     const Calibration& calibration, const Budget& budget) {
  return makePlan(registry, features, calibration, budget, sceneFit(registry, scene, request));
}

}  // namespace lucent::plan
