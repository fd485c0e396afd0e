#pragma once
/// @file volume_sampling.hpp
/// @brief The medium primitives of the path tracers: Henyey-Greenstein direction sampling,
/// free-flight sampling (closed form in a homogeneous medium, delta tracking in a heterogeneous
/// one) and transmittance (closed form, or ratio tracking). Heterogeneous media use one scalar
/// majorant sigma_bar = maxDensity * max_c sigma_t,c for all channels, so the majorant
/// transmittances cancel in the hero-channel weights and only the real/null collision factors
/// remain (Novak et al. 2014).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "../optics/constants.hpp"
#include "../optics/phase_hg.hpp"
#include "../util/basis.hpp"
#include "../util/rng.hpp"
#include "hero_channel_weight.hpp"
#include "participating_media.hpp"

namespace lucent::reference {

/// A new propagation direction after scattering from direction `d`; the HG pdf cancels the phase
/// value, so the path weight is unchanged.
inline glm::dvec3 scatterHG(const glm::dvec3& d, double g, util::Rng& rng) {
  const double cosT = optics::sampleCosThetaHG(rng.uniform(), g);
  const double sinT = std::sqrt(std::max(0.0, 1 - cosT * cosT));
  const double phi = 2 * optics::kPi * rng.uniform();
  glm::dvec3 t, u;
  util::orthonormalBasis(d, t, u);
  return glm::normalize(sinT * std::cos(phi) * t + sinT * std::sin(phi) * u + cosT * d);
}

inline double maxComponent(const glm::dvec3& v) { return std::max(v.x, std::max(v.y, v.z)); }

/// Russian roulette after the third scatter, on the physical throughput: the weight without the
/// radiance scaling of the refractions so far (pbrt-v4's etaScale), which the exit undoes. Read as a
/// loss, the entry's (1/1.3)^2 = 0.59 ended 41 % of the paths in a medium of eta 1.3 at their 4th
/// scatter, even without absorption. False: the path ends; else `w` carries the survival's 1/q.
inline bool survivesRoulette(HeroChannelWeight& w, double radianceScale, int scatters,
                             util::Rng& rng) {
  if (scatters <= 3) return true;
  const double throughput = maxComponent(w.value()) / radianceScale;
  if (throughput >= 1) return true;
  const double q = std::max(0.05, throughput);
  if (rng.uniform() >= q) return false;
  w.scale(glm::dvec3(1 / q));
  return true;
}

/// Counts of what a tracer had to correct; tests assert they stay zero where they must.
struct MediumSamplingStats {
  std::uint64_t majorantViolations = 0;  ///< density above maxDensity (clamped: biased there)
};

namespace detail {
inline double densityAt(const Medium& m, const glm::dvec3& x, MediumSamplingStats& stats) {
  const double d = m.density(x);
  if (!(d <= m.maxDensity)) {  // also catches NaN
    ++stats.majorantViolations;
    return std::isnan(d) ? 0.0 : m.maxDensity;
  }
  return std::max(0.0, d);
}

/// sigma_s and sigma_t at x of a heterogeneous medium: its field, or its constants times the
/// density.
struct LocalCoefficients {
  glm::dvec3 sigmaS, sigmaT;
};
inline LocalCoefficients localCoefficients(const Medium& m, const glm::dvec3& x,
                                           MediumSamplingStats& stats) {
  if (m.coefficients) {
    const auto [sigmaA, sigmaS] = m.coefficients(x);
    LocalCoefficients c{glm::max(sigmaS, glm::dvec3(0)), glm::max(sigmaA + sigmaS, glm::dvec3(0))};
    const double top = std::max(c.sigmaT.x, std::max(c.sigmaT.y, c.sigmaT.z));
    if (!(top <= m.maxSigmaT)) {  // also catches NaN
      ++stats.majorantViolations;
      const double s = std::isfinite(top) && top > 0 ? m.maxSigmaT / top : 0.0;
      c.sigmaS *= s, c.sigmaT *= s;
    }
    return c;
  }
  const double rho = densityAt(m, x, stats);
  return {rho * m.sigmaS, rho * m.sigmaT()};
}

/// The scalar majorant of delta and ratio tracking.
inline double majorant(const Medium& m) {
  return m.coefficients
             ? m.maxSigmaT
             : m.maxDensity * std::max(m.sigmaT().x, std::max(m.sigmaT().y, m.sigmaT().z));
}
}  // namespace detail

/// Samples where the next collision along (x, d) happens before `tBoundary`. Returns true and sets
/// `t` for a real (scattering) collision, false when the flight reaches the boundary; `w` takes the
/// factors of that event for every channel (its pdf for each would-be hero, its contribution per
/// channel).
/// In a homogeneous medium, the distance to the next collision drawn for the hero channel
/// (infinite where the hero's extinction is 0). Drawn before the boundary is known, so a flight
/// that surely ends before any surface needs no ray cast (surface_clearance_grid.hpp).
inline double drawHomogeneousFlight(const Medium& m, int hero, util::Rng& rng) {
  const double sh = m.sigmaT()[hero];
  return sh > 0 ? -std::log(1 - rng.uniform()) / sh : std::numeric_limits<double>::infinity();
}

/// The rest of sampleFlight in a homogeneous medium, for a distance t drawn by
/// drawHomogeneousFlight: true (a collision at t) when t < tBoundary.
inline bool finishHomogeneousFlight(const Medium& m, double t, double tBoundary,
                                    HeroChannelWeight& w) {
  const glm::dvec3 sigmaT = m.sigmaT();
  if (t >= tBoundary) {
    const glm::dvec3 tr = glm::exp(-sigmaT * tBoundary);
    w.scale(tr, tr);
    return false;
  }
  const glm::dvec3 tr = glm::exp(-sigmaT * t);
  w.scale(m.sigmaS * tr, sigmaT * tr);
  return true;
}

inline bool sampleFlight(const Medium& m, const glm::dvec3& x, const glm::dvec3& d,
                         double tBoundary, int hero, util::Rng& rng, HeroChannelWeight& w,
                         double& t, MediumSamplingStats& stats) {
  if (m.homogeneous()) {
    t = drawHomogeneousFlight(m, hero, rng);
    return finishHomogeneousFlight(m, t, tBoundary, w);
  }
  const double sigmaBar = detail::majorant(m);
  if (!(sigmaBar > 0)) return false;
  t = 0;
  for (;;) {
    t -= std::log(1 - rng.uniform()) / sigmaBar;
    if (t >= tBoundary) return false;  // the majorant transmittance is common to every channel
    const detail::LocalCoefficients local = detail::localCoefficients(m, x + t * d, stats);
    const glm::dvec3 sigmaTx = local.sigmaT;
    if (rng.uniform() * sigmaBar < sigmaTx[hero]) {
      w.scale(local.sigmaS, sigmaTx);
      return true;
    }
    const glm::dvec3 nullPart = glm::dvec3(sigmaBar) - sigmaTx;
    w.scale(nullPart, nullPart);
  }
}

/// Transmittance along a segment of length `length` inside one medium: exact when homogeneous, an
/// unbiased ratio-tracking estimate otherwise.
inline glm::dvec3 transmittance(const Medium& m, const glm::dvec3& x, const glm::dvec3& d,
                                double length, util::Rng& rng, MediumSamplingStats& stats) {
  const glm::dvec3 sigmaT = m.sigmaT();
  if (m.homogeneous()) return glm::exp(-sigmaT * length);
  const double sigmaBar = detail::majorant(m);
  glm::dvec3 tr(1);
  if (!(sigmaBar > 0)) return tr;
  if (!std::isfinite(length)) return glm::dvec3(0);  // an endless segment: the walk would not end
  for (double t = 0;;) {
    t -= std::log(1 - rng.uniform()) / sigmaBar;
    if (t >= length) return tr;
    tr *= glm::dvec3(1) - detail::localCoefficients(m, x + t * d, stats).sigmaT / sigmaBar;
    if (maxComponent(tr) < 1e-12) return glm::dvec3(0);  // negligible; stop walking
  }
}

}  // namespace lucent::reference
