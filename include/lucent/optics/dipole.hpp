#pragma once
/// @file dipole.hpp
/// @brief The dipole diffusion profile Rd(r) of Jensen et al. 2001 (Table 1 of
/// Chang et al. 2008), its closed-form radial integral and total diffuse reflectance.
///
/// All lengths in mm, coefficients in mm^-1. Every function is finite for sigma_a = 0 (spectralon:
/// sigma_tr = 0, no exponential fall-off), for sigma_s' = 0 (clear liquids: alpha' = 0, Rd = 0), for
/// r = 0 and for r -> infinity.
#include <cmath>
#include <limits>

#include "constants.hpp"
#include "fresnel.hpp"
#include "rgb.hpp"

namespace lucent::optics {

/// @brief The derived quantities of one colour channel that Rd(r) needs.
template <class T>
struct DipoleChannel {
  T sigmaTr = 0;     ///< effective transport coefficient sqrt(3 sigma_a sigma_t')
  T zr = 1;          ///< depth of the real source, 1/sigma_t' (= mean free path l_u)
  T zv = 1;          ///< height of the virtual source, zr (1 + 4A/3)
  T alphaPrime = 0;  ///< reduced albedo sigma_s'/sigma_t'; 0 means "no scattering": Rd = 0

  /// @param sigmaA absorption coefficient, >= 0
  /// @param sigmaSPrime reduced scattering coefficient, >= 0
  /// @param eta relative index of refraction in [kEtaMin, kEtaMax]
  static DipoleChannel make(T sigmaA, T sigmaSPrime, T eta) {
    DipoleChannel c;
    const T sigmaTPrime = sigmaA + sigmaSPrime;
    if (!(sigmaTPrime > T(0)) || !(sigmaSPrime > T(0))) return c;  // nothing scatters: Rd == 0
    c.alphaPrime = sigmaSPrime / sigmaTPrime;
    c.sigmaTr = std::sqrt(T(3) * sigmaA * sigmaTPrime);
    c.zr = T(1) / sigmaTPrime;
    c.zv = c.zr * (T(1) + T(4) / T(3) * boundaryMismatch(eta));
    return c;
  }

  /// Mean free path l_u = 1/sigma_t' (mm).
  T meanFreePath() const { return zr; }

  /// @brief Rd(r) in mm^-2 (Table 1: the real and the virtual source).
  T rd(T r) const {
    if (alphaPrime <= T(0) || !(r < std::numeric_limits<T>::infinity())) return T(0);
    return alphaPrime * T(1.0 / (4.0 * kPi)) * (pole(zr, r) + pole(zv, r));
  }

  /// @brief 2 pi * integral_0^rho Rd(r) r dr: the fraction of light leaving within radius rho.
  /// Closed form: with d = sqrt(r^2+z^2), d dd = r dr and d/dd(-e^{-s d}/d) = (1+s d) e^{-s d}/d^2.
  T cumulative(T rho) const {
    if (alphaPrime <= T(0)) return T(0);
    return alphaPrime * T(0.5) * (poleIntegral(zr, rho) + poleIntegral(zv, rho));
  }

  /// @brief Total diffuse reflectance, 2 pi * integral_0^inf Rd(r) r dr
  /// = (alpha'/2)(1 + e^{-(4/3) A sqrt(3(1-alpha'))}) e^{-sqrt(3(1-alpha'))} (Jensen 2001, Eq. 14).
  T total() const {
    if (alphaPrime <= T(0)) return T(0);
    return alphaPrime * T(0.5) * (std::exp(-sigmaTr * zr) + std::exp(-sigmaTr * zv));
  }

 private:
  T pole(T z, T r) const {
    const T d = std::hypot(r, z);  // no overflow of r*r for huge r
    const T sd = sigmaTr * d;
    const T e = std::exp(-sd);
    if (e == T(0)) return T(0);  // else (1 + sd) e is inf * 0 = NaN for astronomically large r
    return z * (T(1) + sd) * e / (d * d * d);
  }
  T poleIntegral(T z, T rho) const {
    const T inner = std::exp(-sigmaTr * z);
    if (!(rho < std::numeric_limits<T>::infinity())) return inner;
    const T d = std::sqrt(rho * rho + z * z);
    return inner - z * std::exp(-sigmaTr * d) / d;
  }
};

/// @brief The dipole of a material in three channels.
template <class T>
struct Dipole {
  DipoleChannel<T> channel[kChannels];
  T eta = T(1.3);

  static Dipole make(const Rgb<T>& sigmaA, const Rgb<T>& sigmaSPrime, T eta) {
    Dipole d;
    d.eta = eta;
    for (int c = 0; c < kChannels; ++c) d.channel[c] = DipoleChannel<T>::make(sigmaA[c], sigmaSPrime[c], eta);
    return d;
  }

  Rgb<T> rd(T r) const { return {channel[0].rd(r), channel[1].rd(r), channel[2].rd(r)}; }
  Rgb<T> cumulative(T rho) const {
    return {channel[0].cumulative(rho), channel[1].cumulative(rho), channel[2].cumulative(rho)};
  }
  Rgb<T> total() const { return {channel[0].total(), channel[1].total(), channel[2].total()}; }
  Rgb<T> sigmaTr() const { return {channel[0].sigmaTr, channel[1].sigmaTr, channel[2].sigmaTr}; }

  /// Smallest mean free path over the channels: the length scale that sample spacing must resolve.
  T minMeanFreePath() const {
    T m = std::numeric_limits<T>::infinity();
    for (const auto& c : channel)
      if (c.alphaPrime > T(0) && c.zr < m) m = c.zr;
    return m;
  }
};

}  // namespace lucent::optics
