#pragma once
/// @file terms.hpp
/// @brief Which light-transport terms a scene calls for, each decided from a physical ratio and
/// the user's target error, with the reason in one line: Rd's reach against a pixel (below it a
/// diffuse BRDF is enough), the light that crosses the object from behind against the target
/// (local or global multiple scattering), and the measured share of single scattering on the
/// most similar measured scene.
#include <cmath>
#include <string>
#include <vector>

#include "../technique/capabilities.hpp"
#include "../technique/validity.hpp"
#include "calibration.hpp"
#include "prediction.hpp"

namespace lucent::plan {

struct TermDecision {
  std::string term;
  bool simulated = false;
  std::string reason;
};

/// What the chosen technique must be able to do.
struct TermPlan {
  std::vector<TermDecision> terms;
  technique::Reach reach = technique::Reach::Global;  ///< the least reach that serves the scene
  bool singleScattering = false;
  bool lit = true;           ///< false: no light reaches the object, nothing to simulate
  double singleShare = NAN;  ///< measured on the nearest scene (NaN: no measurement)
  double globalShare = 0;    ///< the light's share that reaches the viewer across the object
};

namespace detail {
inline std::string pct(double share) { return technique::numberText(100 * share) + " %"; }

/// The single-scattering share of the most similar scene measured for the dipole (the model
/// whose floor the path tracer measured with and without single scattering).
inline Neighbours singleShareOf(const SceneFeatures& f, const Calibration& c) {
  std::vector<const ModelFloor*> rows;
  for (const auto& r : c.floors) rows.push_back(&r);
  return predictFromNeighbours(
      f, rows, [](const ModelFloor& r) { return r.singleShare; }, 1);
}

/// The reach the scene needs: global where the light crossing the object is above the target
/// (whatever a pixel covers), else a point where Rd's reach is below a pixel, else local.
inline void decideReach(const SceneFeatures& f, double threshold, TermPlan& plan) {
  plan.globalShare = f.backLitShare * std::exp(-f.thicknessInDiffusionLengths());
  plan.reach = plan.globalShare > threshold ? technique::Reach::Global
               : f.reachInPixels() < 1      ? technique::Reach::Point
                                            : technique::Reach::Local;
}

inline TermDecision diffuseLimit(const SceneFeatures& f, const TermPlan& plan) {
  const bool subPixel = f.reachInPixels() < 1;
  return {"multiple scattering as a diffuse BRDF (Rd_total)", plan.reach == technique::Reach::Point,
          "99 % of Rd lies within " + technique::lengthText(f.reachMm) + ", " +
              technique::numberText(f.reachInPixels()) + " of a pixel (" +
              technique::lengthText(f.pixelMm) + ")" +
              (!subPixel ? ": the profile spreads light across pixels, a BRDF would lose the glow"
               : plan.reach == technique::Reach::Point
                   ? ": a pixel averages the whole profile, so E Rd_total is the same image"
                   : ", but the light crossing the object needs global transport")};
}

inline TermDecision globalTransport(const SceneFeatures& f, double threshold,
                                    const TermPlan& plan) {
  const bool needed = plan.reach == technique::Reach::Global;
  return {"multiple scattering, global (light crossing the object)", needed,
          pct(f.backLitShare) + " of the light comes from behind the object and a mean chord of " +
              technique::lengthText(f.thicknessMm) + " is " +
              technique::numberText(f.thicknessInDiffusionLengths()) +
              " diffusion lengths: about " + pct(plan.globalShare) +
              " reaches the viewer through it (back-lit share x e^-chord/l_d), " +
              (needed ? "above" : "below") + " the " + pct(threshold) + " target"};
}

inline TermDecision singleScattering(const SceneFeatures& f, const Calibration& c, double threshold,
                                     TermPlan& plan) {
  const Neighbours n = singleShareOf(f, c);
  plan.singleShare = n.value;
  if (std::isnan(n.value))
    return {"single scattering", false,
            "no measurement of its share (no model floors in " + c.source + ")"};
  plan.singleScattering = n.value > threshold;
  return {"single scattering", plan.singleScattering,
          "it carries " + pct(n.value) + " of the light on the most similar measured scene (" +
              n.nearestScene + ", path tracer with and without it), " +
              (plan.singleScattering ? "above" : "below") + " the " + pct(threshold) + " target"};
}
}  // namespace detail

/// The terms of a scene at a target error (relative RMS against the physical truth).
inline TermPlan decideTerms(const SceneFeatures& f, const Calibration& c, double threshold) {
  TermPlan plan;
  if (!(f.light > 0)) {
    plan.lit = false;
    plan.reach = technique::Reach::Point;
    plan.terms.push_back({"every term", false,
                          "no light reaches the object: the image is black whatever is simulated"});
    return plan;
  }
  plan.terms.push_back(
      {"first-surface reflection", false,
       "lucent's dipole, diffusion and voxel techniques render the light that entered the "
       "object; the host renderer's specular BRDF adds the reflection"});
  detail::decideReach(f, threshold, plan);
  plan.terms.push_back(detail::diffuseLimit(f, plan));
  plan.terms.push_back({"multiple scattering, local (around the lit point)",
                        plan.reach != technique::Reach::Point,
                        plan.reach == technique::Reach::Point
                            ? "inside the pixel: the diffuse BRDF holds it"
                            : "the dominant term wherever light enters a medium of albedo " +
                                  technique::numberText(f.albedo)});
  plan.terms.push_back(detail::globalTransport(f, threshold, plan));
  plan.terms.push_back(detail::singleScattering(f, c, threshold, plan));
  if (f.environment())
    plan.terms.push_back({"all-frequency environment relighting (wavelet PRT)", false,
                          "an environment light on a static shape is PRT's case; lucent has no "
                          "PRT technique yet, so the environment is integrated per frame"});
  return plan;
}

}  // namespace lucent::plan
