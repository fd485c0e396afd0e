#pragma once
/// @file beam_diffusion.hpp
/// @brief Photon beam diffusion (Habel, Christensen, Jarosz 2013, "Photon Beam Diffusion: A Hybrid
/// Monte Carlo Method for Subsurface Scattering", EGSR 2013, Sec. 3-4): the profile of a pencil
/// beam as the better dipole integrated along the refracted beam, plus the beam's single
/// scattering, tabulated over the optical radius r sigma_t' for one channel.
///
/// Multiple scattering (Eq. 10-12): R_ms(r) = int_0^inf e^{-t} kappa(t) rho'^2 R_t(r) dt in optical
/// units (sigma_t' = 1), where R_t is the better dipole (dipole.hpp) with its real source at depth
/// t and kappa = 1 - e^{-2 (d_r + t)} removes sources closer to the exit point than the diffusion
/// can see. Single scattering (Eq. 6): R_ss(r) = int_{t_c}^inf rho e^{-t} e^{-d} p(cos) Ft(cos) cos
/// / d^2 dt, d = sqrt(r^2 + t^2), cos = t / d, isotropic phase (the medium is given by its reduced
/// coefficients, as for the pencil-beam Monte Carlo), t_c = r sqrt(eta^2 - 1) where total internal
/// reflection ends.
///
/// Both integrals use composite 8-point Gauss-Legendre on panels that grow geometrically from the
/// integrand's own scale (r); the table then holds 24 radii per decade from 1e-4 to 1e3 optical
/// radii, interpolated as a power law between nodes (exact for the 1/r^3 tail of zero absorption),
/// and the cumulative profile is the exact integral of that interpolant. Beyond 1e3 mean free paths
/// the profile is 0 (at zero absorption that drops about 0.1 % of the total; with any absorption
/// nothing visible). Below 1e-4 it is the value at 1e-4 (R_ms diverges as log(1/r), R_ss as 1/r:
/// both integrable).
///
/// Not energy-conserving near zero absorption: every first collision feeds the diffusion sources
/// and the single scattering counts again what leaves after it, so at albedo 1 the total is 1.091
/// at eta 1 (multiple 0.938 + single 0.153), 1.033 at eta 1.3, 1.019 at eta 1.5 (tests and
/// docs/accuracy/profiles.md); the Monte Carlo gives 1. This is the model as published and
/// tabulated.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "constants.hpp"
#include "dipole.hpp"
#include "fresnel.hpp"
#include "fresnel_moments.hpp"

namespace lucent::optics {

/// The beam-diffusion profile of one channel in optical units: radii in mean free paths 1/sigma_t'.
class BeamDiffusionProfile {
 public:
  static constexpr double kFirstRadius = 1e-4;  ///< optical radius of the first node
  static constexpr double kLastRadius = 1e3;    ///< optical radius of the last node
  static constexpr int kNodesPerDecade = 24;

  static constexpr int nodeCount() {
    return 7 * kNodesPerDecade + 1;  // 7 decades, kFirstRadius to kLastRadius
  }
  static double nodeRadius(int i) {
    return kFirstRadius * std::pow(10.0, double(i) / kNodesPerDecade);
  }

  /// By quadrature at every node. @param albedo reduced albedo rho' = sigma_s' / sigma_t' in
  /// [0, 1]; @param eta relative index; @param c1, c2 the internal Fresnel moments of eta
  /// (fresnel_moments.hpp).
  BeamDiffusionProfile(double albedo, double eta, double c1, double c2)
      : mAlbedo(std::clamp(albedo, 0.0, 1.0)), mEta(eta), mC1(c1), mC2(c2) {
    std::vector<double> values(static_cast<std::size_t>(nodeCount()));
    for (int i = 0; i < nodeCount(); ++i) values[std::size_t(i)] = exact(nodeRadius(i));
    setNodes(std::move(values));
  }
  /// From given node values (BeamDiffusionTable's interpolation across albedos), one per
  /// nodeRadius.
  BeamDiffusionProfile(double albedo, double eta, double c1, double c2, std::vector<double> values)
      : mAlbedo(std::clamp(albedo, 0.0, 1.0)), mEta(eta), mC1(c1), mC2(c2) {
    setNodes(std::move(values));
  }

  /// R(r) evaluated by quadrature (what the table approximates; also the tests' reference).
  double exact(double r, int pointsScale = 1) const {
    return multipleScattering(r, pointsScale) + singleScattering(r, pointsScale);
  }
  double multipleScattering(double r, int pointsScale = 1) const;
  double singleScattering(double r, int pointsScale = 1) const;

  /// Interpolated R at optical radius r (per unit optical area).
  double operator()(double r) const {
    if (!(r < kLastRadius)) return 0;
    if (!(r > mRadius[0])) return mValue[0];
    const std::size_t i = segmentOf(r);
    return interpolate(i, r);
  }
  /// 2 pi int_0^r R(r') r' dr' of the interpolant.
  double cumulative(double r) const {
    if (!(r > 0)) return 0;
    if (!(r < kLastRadius)) return mCumulative.back();
    if (r <= mRadius[0]) return kPi * r * r * mValue[0];
    const std::size_t i = segmentOf(r);
    return mCumulative[i] + segmentIntegral(i, r);
  }
  double total() const { return mCumulative.back(); }
  double albedo() const { return mAlbedo; }
  std::size_t nodes() const { return mRadius.size(); }
  const std::vector<double>& nodeValues() const { return mValue; }

 private:
  void setNodes(std::vector<double> values) {
    mValue = std::move(values);
    mRadius.resize(mValue.size());
    mCumulative.resize(mValue.size());
    for (std::size_t i = 0; i < mValue.size(); ++i) mRadius[i] = nodeRadius(int(i));
    // The disc below the first node holds the first value; then each segment's exact integral.
    mCumulative[0] = kPi * mRadius[0] * mRadius[0] * mValue[0];
    for (std::size_t i = 1; i < mRadius.size(); ++i)
      mCumulative[i] = mCumulative[i - 1] + segmentIntegral(i - 1, mRadius[i]);
  }
  std::size_t segmentOf(double r) const {
    const double u = std::log10(r / kFirstRadius) * kNodesPerDecade;
    return std::min(std::size_t(std::max(u, 0.0)), mRadius.size() - 2);
  }
  /// Power law between positive nodes (linear when a node is 0, e.g. an underflowed far tail).
  double interpolate(std::size_t i, double r) const {
    const double v0 = mValue[i], v1 = mValue[i + 1];
    if (v0 > 0 && v1 > 0) return v0 * std::pow(r / mRadius[i], slope(i));
    return v0 + (v1 - v0) * (r - mRadius[i]) / (mRadius[i + 1] - mRadius[i]);
  }
  double slope(std::size_t i) const {
    return std::log(mValue[i + 1] / mValue[i]) / std::log(mRadius[i + 1] / mRadius[i]);
  }
  /// 2 pi int_{r_i}^{r} R r dr of the interpolant on segment i.
  double segmentIntegral(std::size_t i, double r) const {
    const double r0 = mRadius[i], v0 = mValue[i], v1 = mValue[i + 1];
    if (v0 > 0 && v1 > 0) {
      const double e = slope(i) + 2, l = std::log(r / r0);
      const double growth = std::abs(e * l) < 1e-12 ? l : std::expm1(e * l) / e;
      return 2 * kPi * v0 * r0 * r0 * growth;
    }
    const double k = (v1 - v0) / (mRadius[i + 1] - r0);  // v = v0 + k (r - r0)
    const auto antiderivative = [&](double x) {
      return (v0 - k * r0) * x * x / 2 + k * x * x * x / 3;
    };
    return 2 * kPi * (antiderivative(r) - antiderivative(r0));
  }

  double mAlbedo, mEta, mC1, mC2;
  std::vector<double> mRadius, mValue, mCumulative;
};

namespace detail {
/// 8-point Gauss-Legendre on [0, 1].
inline constexpr std::array<double, 8> kGaussNode{
    0.0198550717512319, 0.1016667612931866, 0.2372337950418355, 0.4082826787521751,
    0.5917173212478249, 0.7627662049581645, 0.8983332387068134, 0.9801449282487681};
inline constexpr std::array<double, 8> kGaussWeight{
    0.0506142681451881, 0.1111905172266872, 0.1568533229389436, 0.1813418916891810,
    0.1813418916891810, 0.1568533229389436, 0.1111905172266872, 0.0506142681451881};

/// int_start^inf f(t) dt for f decaying at least as e^{-t}: panels [start + s_k, start + s_{k+1}]
/// with s_0 = 0, s_1 = 1e-3 scale, s_{k+1} = 2 s_k up to 50 optical depths; pointsScale > 1
/// subdivides each panel (the convergence check of the tests).
template <class F>
double depthIntegral(const F& f, double start, double scale, int pointsScale) {
  double sum = 0, lo = 0, hi = 1e-3 * std::max(scale, 1e-12);
  while (lo < 50) {
    const double h = (hi - lo) / pointsScale;
    for (int p = 0; p < pointsScale; ++p)
      for (std::size_t g = 0; g < kGaussNode.size(); ++g)
        sum += kGaussWeight[g] * h * f(start + lo + h * (p + kGaussNode[g]));
    lo = hi;
    hi = 2 * hi;
  }
  return sum;
}
}  // namespace detail

inline double BeamDiffusionProfile::multipleScattering(double r, int pointsScale) const {
  if (!(mAlbedo > 0)) return 0;
  // The better dipole of the medium in optical units (sigma_t' = 1); each depth moves both sources.
  const DipoleChannel<double> base =
      DipoleChannel<double>::makeBetter(1 - mAlbedo, mAlbedo, mC1, mC2);
  const double virtualHeight = base.zv - base.zr;  // 4 A D, the same at every depth
  const auto integrand = [&](double t) {
    DipoleChannel<double> c = base;
    c.zr = t;
    c.zv = t + virtualHeight;
    c.alphaPrime = 1;  // the beam's rho'^2 (Habel et al. Eq. 12) is applied here instead
    const double kappa = -std::expm1(-2 * (std::hypot(r, t) + t));
    return std::exp(-t) * kappa * mAlbedo * mAlbedo * c.rd(r);
  };
  return detail::depthIntegral(integrand, 0.0, r, pointsScale);
}

inline double BeamDiffusionProfile::singleScattering(double r, int pointsScale) const {
  if (!(mAlbedo > 0)) return 0;
  const double tCritical = mEta > 1 ? r * std::sqrt(mEta * mEta - 1) : 0.0;
  const auto integrand = [&](double t) {
    const double d = std::hypot(r, t), cosOut = t / d;
    const double ft = fresnelTransmittance(cosOut, 1 / mEta);  // leaving the denser medium
    return mAlbedo * std::exp(-t - d) / (4 * kPi) * ft * cosOut / (d * d);
  };
  return detail::depthIntegral(integrand, tCritical, r, pointsScale);
}

}  // namespace lucent::optics
