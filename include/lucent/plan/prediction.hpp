#pragma once
/// @file prediction.hpp
/// @brief Time and error of a technique setting on a new scene, from its measurements on the
/// calibration scenes. Error: the measured errors of the most similar scenes, similarity read in
/// the dimensionless terms the physics depends on (size in mean free paths, albedo, thickness in
/// diffusion lengths, light from behind, Rd's reach in pixels). Time: a power law in the work a
/// frame scales with (shaded points, surface area in squared mean free paths), fitted by least
/// squares in log space.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "scene_features.hpp"

namespace lucent::plan {

/// The coordinates scenes are compared in, and what each is called in an explanation.
inline constexpr std::array<const char*, 6> kSimilarityNames{
    "size in mean free paths",        "albedo",
    "thickness in diffusion lengths", "back-lit share",
    "Rd's reach in pixels",           "environment share"};

inline std::array<double, 6> similarityCoordinates(const SceneFeatures& f) {
  return {std::log10(std::max(f.sizeInMeanFreePaths(), 1e-9)),  f.albedo,
          std::log10(1 + f.thicknessInDiffusionLengths()),      f.backLitShare,
          std::log10(std::clamp(f.reachInPixels(), 1e-6, 1e6)), f.environmentShare};
}

/// The spread each coordinate is measured in: one decade for the logarithms, a tenth of albedo
/// (the dipole's error changes by that much over 0.1 in albedo near 1), a quarter of the light.
inline constexpr std::array<double, 6> kSimilarityScale{1.0, 0.1, 1.0, 0.25, 1.0, 0.25};

/// Whether a coordinate is a log10 (for the explanation).
inline bool isLogCoordinate(std::size_t k) { return k == 0 || k == 2 || k == 4; }

inline double sceneDistance(const SceneFeatures& a, const SceneFeatures& b) {
  const auto x = similarityCoordinates(a), y = similarityCoordinates(b);
  double d2 = 0;
  for (std::size_t k = 0; k < x.size(); ++k) d2 += std::pow((x[k] - y[k]) / kSimilarityScale[k], 2);
  return std::sqrt(d2);
}

/// A value predicted from neighbours: the inverse-distance weighted geometric mean of the k
/// nearest, with the distance to the nearest (how far the scene is from what was measured).
struct Neighbours {
  double value = NAN;
  double nearestDistance = INFINITY;
  std::string nearestScene;
};

template <class Row, class Value>
Neighbours predictFromNeighbours(const SceneFeatures& f, const std::vector<const Row*>& rows,
                                 const Value& value, std::size_t k = 3) {
  std::vector<std::pair<double, const Row*>> byDistance;
  for (const Row* r : rows) byDistance.emplace_back(sceneDistance(f, r->features), r);
  std::sort(byDistance.begin(), byDistance.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  Neighbours out;
  if (byDistance.empty()) return out;
  out.nearestDistance = byDistance.front().first;
  out.nearestScene = byDistance.front().second->scene;
  double sumW = 0, sumLog = 0;
  for (std::size_t i = 0; i < std::min(k, byDistance.size()); ++i) {
    const double w = 1 / (byDistance[i].first + 0.05);
    sumW += w;
    sumLog += w * std::log(std::max(value(*byDistance[i].second), 1e-9));
  }
  out.value = std::exp(sumLog / sumW);
  return out;
}

/// What a frame's time grows with: log shaded points, log surface area in squared mean free
/// paths (the dipole sums' samples), log triangles (atlas and map rasterisation), the share of
/// environment light (integrated over strata of directions at every sample), and that share
/// times the log area (an environment multiplies the work per sample, not a constant).
inline constexpr std::size_t kCostDrivers = 5;
inline constexpr std::array<const char*, kCostDrivers> kCostDriverNames{
    "points", "area/l_u^2", "triangles", "environment", "environment x log area"};

/// Whether a driver is the log of a count (the law is a power of it) or a share (an exponential).
inline bool isCountDriver(std::size_t k) { return k < 3; }

inline std::array<double, kCostDrivers> costDrivers(const SceneFeatures& f) {
  const double logArea = std::log(std::max(f.areaInMeanFreePaths2(), 1.0));
  return {std::log(std::max(f.shadedPoints, 1.0)), logArea, std::log(std::max(f.triangles, 1.0)),
          f.environmentShare, f.environmentShare * logArea};
}

/// t = exp(intercept + sum_k slope_k driver_k): a power law in the counts, exponential in the
/// environment share.
struct PowerLaw {
  double intercept = 0;
  std::array<double, kCostDrivers> slope{1, 0, 0, 0,
                                         0};  ///< linear in the points, nothing else, until fitted
  double operator()(const SceneFeatures& f) const {
    const auto x = costDrivers(f);
    double v = intercept;
    for (std::size_t k = 0; k < x.size(); ++k) v += slope[k] * x[k];
    return std::exp(v);
  }
};

namespace detail {
/// Solves the n x n system m x = m[.][n] in place (Gauss-Jordan, partial pivoting); false when
/// singular.
template <std::size_t N>
bool solve(std::array<std::array<double, N + 1>, N>& m) {
  for (std::size_t col = 0; col < N; ++col) {
    std::size_t pivot = col;
    for (std::size_t i = col + 1; i < N; ++i)
      if (std::abs(m[i][col]) > std::abs(m[pivot][col])) pivot = i;
    std::swap(m[col], m[pivot]);
    if (!(std::abs(m[col][col]) > 1e-12)) return false;
    for (std::size_t i = 0; i < N; ++i) {
      if (i == col) continue;
      const double f = m[i][col] / m[col][col];
      for (std::size_t j = col; j <= N; ++j) m[i][j] -= f * m[col][j];
    }
  }
  for (std::size_t i = 0; i < N; ++i) m[i][N] /= m[i][i];
  return true;
}
}  // namespace detail

/// Fits the power law to measured seconds by least squares on the logarithms, each slope pulled
/// weakly towards the unfitted law (linear in the points), so that a setting measured on few or
/// alike scenes extrapolates as plain per-point work; slopes are kept within what any technique's
/// work grows with.
template <class Row, class Seconds>
PowerLaw fitPowerLaw(const std::vector<const Row*>& rows, const Seconds& seconds) {
  constexpr std::size_t n = kCostDrivers + 1;  // intercept + slopes
  const PowerLaw prior;
  const double lambda = 0.1 * double(rows.size());
  std::array<std::array<double, n + 1>, n> m{};
  for (std::size_t k = 1; k < n; ++k) m[k][k] += lambda, m[k][n] += lambda * prior.slope[k - 1];
  for (const Row* r : rows) {
    const auto d = costDrivers(r->features);
    double v[n] = {1};
    for (std::size_t k = 0; k < kCostDrivers; ++k) v[k + 1] = d[k];
    const double t = std::log(std::max(seconds(*r), 1e-6));
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) m[i][j] += v[i] * v[j];
      m[i][n] += v[i] * t;
    }
  }
  PowerLaw p;
  if (rows.empty() || !detail::solve<n>(m)) return p;
  for (std::size_t k = 0; k < kCostDrivers; ++k) p.slope[k] = std::clamp(m[k + 1][n], -1.0, 3.0);
  double sum = 0;  // the intercept refitted to the clamped slopes
  for (const Row* r : rows) {
    const auto d = costDrivers(r->features);
    double v = std::log(std::max(seconds(*r), 1e-6));
    for (std::size_t k = 0; k < kCostDrivers; ++k) v -= p.slope[k] * d[k];
    sum += v;
  }
  p.intercept = sum / double(rows.size());
  return p;
}

/// The power law corrected by what it missed on the measured scenes nearest in cost drivers: its
/// log residuals there, inverse-distance weighted, so a scene like a measured one inherits its
/// measured time. (Shrinking the correction with distance was tried: leave one out, it predicted
/// worse, x2.14 against x2.13 log-RMS.)
struct TimeModel {
  PowerLaw law;
  std::vector<std::pair<std::array<double, kCostDrivers>, double>>
      residuals;  ///< (drivers, log residual)

  double operator()(const SceneFeatures& f) const {
    const auto x = costDrivers(f);
    std::vector<std::pair<double, double>> byDistance;  // (distance, residual)
    for (const auto& [d, r] : residuals) {
      double d2 = 0;
      for (std::size_t k = 0; k < x.size(); ++k) d2 += std::pow((x[k] - d[k]) / kCostScale[k], 2);
      byDistance.emplace_back(std::sqrt(d2), r);
    }
    std::sort(byDistance.begin(), byDistance.end());
    double sumW = 0, sum = 0;
    for (std::size_t i = 0; i < std::min<std::size_t>(2, byDistance.size()); ++i) {
      const double w = 1 / (byDistance[i].first + 0.05);
      sumW += w, sum += w * byDistance[i].second;
    }
    const double correction = sumW > 0 ? sum / sumW : 0;
    return law(f) * std::exp(correction);
  }
  /// One unit of each cost driver: a factor e in area and triangles, e^3 in points (the law's
  /// points slope carries a change of resolution, so the same object at another resolution is a
  /// near neighbour), half the environment share.
  static constexpr std::array<double, kCostDrivers> kCostScale{3, 1, 1, 0.5,
                                                               1e9};  // the product: not a distance
};

template <class Row, class Seconds>
TimeModel fitTimeModel(const std::vector<const Row*>& rows, const Seconds& seconds) {
  TimeModel m;
  m.law = fitPowerLaw(rows, seconds);
  for (const Row* r : rows)
    m.residuals.emplace_back(costDrivers(r->features),
                             std::log(std::max(seconds(*r), 1e-6)) - std::log(m.law(r->features)));
  return m;
}

}  // namespace lucent::plan
