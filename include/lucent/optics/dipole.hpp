#pragma once
/// @file dipole.hpp
/// @brief The dipole diffusion profile Rd(r) of Jensen et al. 2001 (Table 1 of
/// Chang et al. 2008) and d'Eon's better dipole (d'Eon 2012), their closed-form radial integrals
/// and total diffuse reflectances. Both are a real and a virtual source; the better dipole takes
/// Grosjean's diffusion coefficient, the boundary condition from the exact Fresnel moments, and
/// counts the fluence as well as the flux in what leaves (R = C_phi phi + C_E E, d'Eon 2012 Eq.
/// 5-9).
///
/// All lengths in mm, coefficients in mm^-1. Every function is finite for sigma_a = 0 (spectralon:
/// sigma_tr = 0, no exponential fall-off), for sigma_s' = 0 (clear liquids: alpha' = 0, Rd = 0),
/// for r = 0 and for r -> infinity.
#include <cmath>
#include <limits>

#include "constants.hpp"
#include "fresnel.hpp"
#include "rgb.hpp"

namespace lucent::optics {

/// @brief The derived quantities of one colour channel that Rd(r) needs.
template <class T>
struct DipoleChannel {
  T sigmaTr = 0;        ///< effective transport coefficient sqrt(3 sigma_a sigma_t')
  T zr = 1;             ///< depth of the real source, 1/sigma_t' (= mean free path l_u)
  T zv = 1;             ///< height of the virtual source, zr (1 + 4A/3)
  T alphaPrime = 0;     ///< reduced albedo sigma_s'/sigma_t'; 0 means "no scattering": Rd = 0
  T fluxWeight = 1;     ///< C_E, the weight of the flux -D dphi/dz (classic dipole: 1)
  T fluenceWeight = 0;  ///< C_phi / D (mm^-1), the weight of the fluence (classic dipole: 0)

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

  /// @brief The better dipole (d'Eon 2012): D = (2 sigma_a + sigma_s') / (3 sigma_t'^2) (Grosjean),
  /// sigma_tr = sqrt(sigma_a / D), the virtual source 2 z_b = 4 A D above the surface with
  /// A = (1 + 3 C_2) / (1 - 2 C_1), and R = C_phi phi + C_E E with C_phi = (1 - 2 C_1) / 4,
  /// C_E = (1 - 3 C_2) / 2 (C_k the internal Fresnel moments, fresnel_moments.hpp). At sigma_a = 0
  /// the total is exactly 1 for every eta.
  static DipoleChannel makeBetter(T sigmaA, T sigmaSPrime, T c1, T c2) {
    DipoleChannel c;
    const T sigmaTPrime = sigmaA + sigmaSPrime;
    if (!(sigmaTPrime > T(0)) || !(sigmaSPrime > T(0))) return c;
    const T d = (T(2) * sigmaA + sigmaSPrime) / (T(3) * sigmaTPrime * sigmaTPrime);
    const T a = (T(1) + T(3) * c2) / (T(1) - T(2) * c1);
    c.alphaPrime = sigmaSPrime / sigmaTPrime;
    c.sigmaTr = std::sqrt(sigmaA / d);
    c.zr = T(1) / sigmaTPrime;
    c.zv = c.zr + T(4) * a * d;
    c.fluxWeight = (T(1) - T(3) * c2) / T(2);
    c.fluenceWeight = (T(1) - T(2) * c1) / (T(4) * d);
    return c;
  }

  /// Mean free path l_u = 1/sigma_t' (mm).
  T meanFreePath() const { return zr; }

  /// @brief Rd(r) in mm^-2 (Table 1: the real and the virtual source; d'Eon 2012 Eq. 9 with the
  /// fluence).
  T rd(T r) const {
    if (alphaPrime <= T(0) || !(r < std::numeric_limits<T>::infinity())) return T(0);
    T flux = fluxWeight * (pole(zr, r) + pole(zv, r));
    if (fluenceWeight != T(0)) flux += fluenceWeight * fluenceDifference(r);
    return alphaPrime * T(1.0 / (4.0 * kPi)) * flux;
  }

  /// @brief 2 pi * integral_0^rho Rd(r) r dr: the fraction of light leaving within radius rho.
  /// Closed form: with d = sqrt(r^2+z^2), d dd = r dr and d/dd(-e^{-s d}/d) = (1+s d) e^{-s d}/d^2;
  /// the fluence terms integrate to (e^{-s z} - e^{-s d(rho)}) / s.
  T cumulative(T rho) const {
    if (alphaPrime <= T(0)) return T(0);
    T sum = fluxWeight * (poleIntegral(zr, rho) + poleIntegral(zv, rho));
    if (fluenceWeight != T(0)) {
      T far = T(0);
      if (rho < std::numeric_limits<T>::infinity())
        far = expDifferenceOverSigma(std::hypot(rho, zr), std::hypot(rho, zv));
      sum += fluenceWeight * (expDifferenceOverSigma(zr, zv) - far);
    }
    return alphaPrime * T(0.5) * sum;
  }

  /// @brief Total diffuse reflectance, 2 pi * integral_0^inf Rd(r) r dr
  /// = (alpha'/2)(1 + e^{-(4/3) A sqrt(3(1-alpha'))}) e^{-sqrt(3(1-alpha'))} (Jensen 2001, Eq. 14)
  /// for the classic dipole, plus the fluence's (alpha'/2) C_phi/D (e^{-s z_r} - e^{-s z_v}) / s.
  T total() const { return cumulative(std::numeric_limits<T>::infinity()); }

  /// The length Rd falls off over: l_u, or 1/sigma_tr where absorption cuts it shorter.
  T width() const { return sigmaTr > T(0) ? std::min(zr, T(1) / sigmaTr) : zr; }
  /// A distance beyond the peak of Rd(r) 2 pi r (which lies on the scale of z_r).
  T reach() const { return T(4) * zv; }
  bool scatters() const { return alphaPrime > T(0); }

 private:
  T pole(T z, T r) const {
    const T d = std::hypot(r, z);  // no overflow of r*r for huge r
    const T sd = sigmaTr * d;
    const T e = std::exp(-sd);
    if (e == T(0)) return T(0);  // else (1 + sd) e is inf * 0 = NaN for astronomically large r
    return z * (T(1) + sd) * e / (d * d * d);
  }
  /// e^{-s d_r} / d_r - e^{-s d_v} / d_v without cancellation far away, where both terms agree to
  /// many digits: with D = d_v - d_r = (z_v^2 - z_r^2) / (d_v + d_r) it is
  /// e^{-s d_r} (D - d_r expm1(-s D)) / (d_r d_v).
  T fluenceDifference(T r) const {
    const T dr = std::hypot(r, zr), dv = std::hypot(r, zv);
    const T gap = (zv - zr) * (zv + zr) / (dv + dr);
    const T near = std::exp(-sigmaTr * dr);
    if (near == T(0)) return T(0);
    return near * (gap - dr * std::expm1(-sigmaTr * gap)) / (dr * dv);
  }
  /// (e^{-s a} - e^{-s b}) / s for b >= a without cancellation, and b - a at s = 0 (no absorption).
  T expDifferenceOverSigma(T a, T b) const {
    if (!(sigmaTr > T(0))) return b - a;
    return -std::exp(-sigmaTr * a) * std::expm1(-sigmaTr * (b - a)) / sigmaTr;
  }
  /// e^{-s z} - (z/d) e^{-s d}, d = sqrt(rho^2 + z^2), as e^{-s z} ((d - z)/d - (z/d) expm1(-s (d -
  /// z))) with d - z = rho^2 / (d + z): both terms >= 0, no cancellation at small rho.
  T poleIntegral(T z, T rho) const {
    const T inner = std::exp(-sigmaTr * z);
    if (!(rho < std::numeric_limits<T>::infinity())) return inner;
    const T d = std::hypot(rho, z), gap = rho / (d + z) * rho;  // rho / (d + z) <= 1: no overflow
    return inner * (gap / d - z / d * std::expm1(-sigmaTr * gap));
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
    for (int c = 0; c < kChannels; ++c)
      d.channel[c] = DipoleChannel<T>::make(sigmaA[c], sigmaSPrime[c], eta);
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
