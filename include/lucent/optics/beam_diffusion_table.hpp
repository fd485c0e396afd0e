#pragma once
/// @file beam_diffusion_table.hpp
/// @brief Photon beam diffusion tabulated once per index of refraction over reduced albedo and
/// optical radius, the way pbrt does (Pharr, Jakob, Humphreys, "Physically Based Rendering", 3rd
/// ed. 2016, Sec. 15.5): a material's profile is then an interpolation across albedo rows, not a
/// quadrature per node (milliseconds per channel).
///
/// In optical units single scattering is exactly rho' times its value at albedo 1, so it is one
/// row, scaled. Multiple scattering is tabulated as ln(R_ms / rho'^2) (finite at rho' = 0, and the
/// far tail e^{-sigma_tr r} is nearly linear in the logarithm) on rows at q = s^2, s uniform on
/// [0, 1], q = sqrt(1 - rho'): the better dipole's sigma_tr / sigma_t' = q sqrt(3 / (1 + q^2)), and
/// the rows crowd near albedo 1 where the tail turns from e^{-sigma_tr r} into 1/r^3 (uniform rows
/// in q err by 30 % there). Catmull-Rom in s interpolates the logarithms, mirrored at s = 0 (a
/// smooth function of q = s^2 is even in s); where a neighbour underflowed (beyond about 700
/// optical depths) the values themselves are interpolated linearly between the two rows. The error
/// against the quadrature at the exact albedo is tested over eta 1 to 3
/// (tests/unit/test_profiles.cpp): kStatedNodeError per node where R is above 1e-6 of its value at
/// one mean free path, and kStatedTotalError for the total.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "beam_diffusion.hpp"
#include "fresnel_moments.hpp"

namespace lucent::optics {

class BeamDiffusionTable {
 public:
  static constexpr int kAlbedoRows = 128;
  /// Largest relative error of an interpolated node (where R >= 1e-6 R(1 mfp)) and of the total,
  /// against the quadrature at the exact albedo (the test's 151 albedos: at most 2.2e-4 and 6.6e-6
  /// for eta 1 to 1.5, 1.0e-3 and 3.2e-5 at eta 3; 401 albedos crowded at 1 found 1.8e-3 and 5e-5
  /// there, in the far tail).
  static constexpr double kStatedNodeError = 2.5e-3;
  static constexpr double kStatedTotalError = 1e-4;

  /// Single scattering now; each row of multiple scattering when an albedo first needs it (a row
  /// is one quadrature per node, about 2 ms: the first profile of an eta fills at most 12 rows,
  /// 27 ms measured for skin1).
  explicit BeamDiffusionTable(double eta)
      : mEta(eta),
        mC1(internalFresnelMoment(1, eta)),
        mC2(internalFresnelMoment(2, eta)),
        mSingle(nodes()),
        mLogMultiple(std::size_t(kAlbedoRows) * nodes()),
        mRowFilled(std::size_t(kAlbedoRows), false) {
    const BeamDiffusionProfile white = quadrature(1.0);
    for (std::size_t i = 0; i < nodes(); ++i)
      mSingle[i] = white.singleScattering(BeamDiffusionProfile::nodeRadius(int(i)));
  }

  /// The shared table of eta rounded to 1e-6 (so a float 1.3 and a double 1.3 share one), built
  /// on first use (thread-safe; a few dozen etas are kept).
  static std::shared_ptr<const BeamDiffusionTable> forEta(double eta) {
    if (!(eta >= kEtaMin && eta <= kEtaMax))
      throw std::invalid_argument("beam diffusion: eta must be in [" + std::to_string(kEtaMin) +
                                  ", " + std::to_string(kEtaMax) + "], not " + std::to_string(eta));
    static std::mutex mutex;
    static std::map<long long, std::shared_ptr<const BeamDiffusionTable>> cache;
    const long long key = std::llround(eta * 1e6);
    const std::lock_guard<std::mutex> lock(mutex);
    if (const auto it = cache.find(key); it != cache.end()) return it->second;
    if (cache.size() >= kCachedEtas) cache.clear();  // a sweep over eta: keep memory bounded
    return cache[key] = std::make_shared<const BeamDiffusionTable>(double(key) * 1e-6);
  }

  /// The profile of reduced albedo rho', its nodes interpolated across the rows.
  std::shared_ptr<const BeamDiffusionProfile> profile(double albedo) const {
    albedo = std::clamp(albedo, 0.0, 1.0);
    const double u = std::sqrt(std::sqrt(1 - albedo)) * (kAlbedoRows - 1);  // s = sqrt(q)
    const int j = std::min(int(u), kAlbedoRows - 2);
    const double t = u - j;
    std::vector<double> values(nodes());
    const std::lock_guard<std::mutex> lock(mMutex);
    for (int k = std::max(j - 1, 0); k <= std::min(j + 2, kAlbedoRows - 1); ++k) fillRow(k);
    for (std::size_t i = 0; i < nodes(); ++i)
      values[i] = albedo * albedo * interpolatedMultiple(j, t, i) + albedo * mSingle[i];
    return std::make_shared<const BeamDiffusionProfile>(albedo, mEta, mC1, mC2, std::move(values));
  }

  double eta() const { return mEta; }

 private:
  static constexpr std::size_t kCachedEtas = 32;

  static std::size_t nodes() { return std::size_t(BeamDiffusionProfile::nodeCount()); }
  static double albedoOfRow(int j) {
    const double s = double(j) / (kAlbedoRows - 1), q = s * s;
    return 1 - q * q;
  }
  /// A profile used only for its quadratures (no nodes evaluated).
  BeamDiffusionProfile quadrature(double albedo) const {
    return BeamDiffusionProfile(albedo, mEta, mC1, mC2, std::vector<double>(nodes(), 0.0));
  }
  void fillRow(int j) const {
    if (mRowFilled[std::size_t(j)]) return;
    // rho' -> 0 in the last row: R_ms / rho'^2 there is its limit, taken at 1e-6.
    const double albedo = std::max(albedoOfRow(j), 1e-6);
    const BeamDiffusionProfile row = quadrature(albedo);
    for (std::size_t i = 0; i < nodes(); ++i) {
      const double v = row.multipleScattering(BeamDiffusionProfile::nodeRadius(int(i)));
      mLogMultiple[std::size_t(j) * nodes() + i] =
          v > 0 ? std::log(v / (albedo * albedo)) : -std::numeric_limits<double>::infinity();
    }
    mRowFilled[std::size_t(j)] = true;
  }
  double at(int row, std::size_t node) const {
    return mLogMultiple[std::size_t(row) * nodes() + node];
  }

  /// R_ms / rho'^2 at node i between rows j and j + 1 (t in [0, 1]).
  double interpolatedMultiple(int j, double t, std::size_t i) const {
    const double p1 = at(j, i), p2 = at(j + 1, i);
    // The outer neighbours: mirrored at s = 0, extended linearly past the last row.
    const double p0 = j > 0 ? at(j - 1, i) : p2;
    const double p3 = j + 2 < kAlbedoRows ? at(j + 2, i) : 2 * p2 - p1;
    if (!(std::isfinite(p0) && std::isfinite(p1) && std::isfinite(p2) && std::isfinite(p3)))
      return (1 - t) * std::exp(p1) + t * std::exp(p2);  // exp(-inf) = 0
    const double t2 = t * t, t3 = t2 * t;
    return std::exp(0.5 * (2 * p1 + (p2 - p0) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t2 +
                           (3 * p1 - p0 - 3 * p2 + p3) * t3));
  }

  double mEta, mC1, mC2;
  std::vector<double> mSingle;  ///< R_ss at albedo 1 per node (R_ss is linear in rho')
  /// Row-major, kAlbedoRows x nodes: ln(R_ms / rho'^2), filled row by row under mMutex.
  mutable std::vector<double> mLogMultiple;
  mutable std::vector<bool> mRowFilled;
  mutable std::mutex mMutex;
};

/// Beam diffusion for one channel in mm: R(r) = sigma_t'^2 R_opt(r sigma_t'), R_opt from the table
/// of its eta.
template <class T>
struct BeamDiffusionChannel {
  std::shared_ptr<const BeamDiffusionProfile> table;
  T sigmaTPrime = 0;  ///< 0: nothing scatters
  T sigmaTr = 0;      ///< the better dipole's, for the fall-off length

  static BeamDiffusionChannel make(T sigmaA, T sigmaSPrime, T eta, double c1, double c2) {
    BeamDiffusionChannel c;
    const double st = double(sigmaA) + double(sigmaSPrime);
    if (!(st > 0) || !(sigmaSPrime > T(0))) return c;
    c.sigmaTPrime = T(st);
    c.table = BeamDiffusionTable::forEta(double(eta))->profile(double(sigmaSPrime) / st);
    c.sigmaTr = DipoleChannel<T>::makeBetter(sigmaA, sigmaSPrime, T(c1), T(c2)).sigmaTr;
    return c;
  }
  bool scatters() const { return table != nullptr; }
  T rd(T r) const {
    if (!table || !(r < std::numeric_limits<T>::infinity())) return T(0);
    return T(double(sigmaTPrime) * double(sigmaTPrime) * (*table)(double(r * sigmaTPrime)));
  }
  T cumulative(T rho) const {
    return table ? T(table->cumulative(double(rho * sigmaTPrime))) : T(0);
  }
  T total() const { return table ? T(table->total()) : T(0); }
  T meanFreePath() const { return table ? T(1) / sigmaTPrime : T(1); }
  T width() const {
    const T lu = meanFreePath();
    return sigmaTr > T(0) ? std::min(lu, T(1) / sigmaTr) : lu;
  }
  T reach() const { return T(8) * meanFreePath(); }
};

}  // namespace lucent::optics
