#pragma once
/// @file fresnel_moments.hpp
/// @brief Angular moments of the Fresnel reflectance, C_k = int_0^1 Fr(mu) mu^k dmu, exact to the
/// quadrature (no polynomial fit), for the boundary conditions of the better dipole and photon beam
/// diffusion (d'Eon 2012, Sec. 2; Habel, Christensen, Jarosz 2013, Sec. 3) and the exit
/// normalisation of their radiance (Sec. 4 of Habel et al.: the exiting light follows Ft(w)
/// cos(w)).
///
/// Internal moments see light inside the medium (relative index 1/eta at the boundary, total
/// internal reflection below the critical cosine); 2 C_1 is then the diffuse Fresnel reflectance
/// Fdr that the classic dipole takes from the Egan-Hilgeman fit. External moments see light
/// arriving from outside.
#include <cmath>

#include "fresnel.hpp"

namespace lucent::optics {

namespace detail {
/// Composite Simpson on [a, b] of f(mu) mu^k with mu = a + (b - a) s^2, which removes the
/// square-root kink of Fr at the critical angle (a) from the integrand.
template <class F>
double fresnelMomentSimpson(const F& fr, int k, double a, double b) {
  constexpr int kIntervals = 512;  // even; the moments are then exact to about 1e-9
  const auto g = [&](double s) {
    const double mu = a + (b - a) * s * s;
    return fr(mu) * std::pow(mu, k) * 2 * (b - a) * s;  // dmu = 2 (b - a) s ds
  };
  double sum = g(0) + g(1);
  for (int i = 1; i < kIntervals; ++i) sum += (i % 2 ? 4 : 2) * g(double(i) / kIntervals);
  return sum / (3.0 * kIntervals);
}
}  // namespace detail

/// int_0^1 Fr(mu) mu^k dmu for light inside a medium of relative index eta >= 1.
inline double internalFresnelMoment(int k, double eta) {
  if (!(eta > 1)) return 0;  // index-matched: nothing reflects
  const double muCritical = std::sqrt(1 - 1 / (eta * eta));
  const double totalPart =
      std::pow(muCritical, k + 1) / (k + 1);  // Fr = 1 below the critical cosine
  return totalPart +
         detail::fresnelMomentSimpson([eta](double mu) { return fresnelReflectance(mu, 1 / eta); },
                                      k, muCritical, 1.0);
}

/// int_0^1 Fr(mu) mu^k dmu for light arriving from outside a medium of relative index eta >= 1.
inline double externalFresnelMoment(int k, double eta) {
  if (!(eta > 1)) return 0;
  return detail::fresnelMomentSimpson([eta](double mu) { return fresnelReflectance(mu, eta); }, k,
                                      0.0, 1.0);
}

/// The normalisation c of the exiting radiance L(w) = B Ft(w) / (pi c), c = 1 - 2 C_1(external):
/// the hemispherical integral of Ft(w) cos(w) / pi, so that the radiance carries exactly the
/// exitance B.
inline double exitNormalisation(double eta) { return 1 - 2 * externalFresnelMoment(1, eta); }

}  // namespace lucent::optics
