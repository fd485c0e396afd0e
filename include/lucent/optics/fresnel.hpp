#pragma once
/// @file fresnel.hpp
/// @brief Exact dielectric Fresnel reflectance, its transmittance, and the diffuse Fresnel terms Fdr and A.
#include <algorithm>
#include <cmath>

#include "constants.hpp"

namespace lucent::optics {

/// @brief Unpolarised Fresnel reflectance of a smooth dielectric boundary.
/// @param cosIncident cosine between the incident direction and the normal, on the incident side
/// @param eta relative index n_transmitted / n_incident (> 1 entering a denser medium)
/// Returns 1 at grazing incidence and under total internal reflection (possible only for eta < 1).
template <class T>
T fresnelReflectance(T cosIncident, T eta) {
  const T cosI = std::clamp(cosIncident, T(0), T(1));
  if (cosI <= T(0)) return T(1);  // grazing: every formula below is 0/0 there when eta = 1
  const T sin2T = (T(1) - cosI * cosI) / (eta * eta);
  if (sin2T >= T(1)) return T(1);  // total internal reflection
  const T cosT = std::sqrt(T(1) - sin2T);
  const T rs = (cosI - eta * cosT) / (cosI + eta * cosT);
  const T rp = (eta * cosI - cosT) / (eta * cosI + cosT);
  return T(0.5) * (rs * rs + rp * rp);
}

/// @brief Fresnel transmittance Ft(eta, w) = 1 - Fr (Chang et al. 2008 Eq. 2, 4).
template <class T>
T fresnelTransmittance(T cosIncident, T eta) {
  return T(1) - fresnelReflectance(cosIncident, eta);
}

/// @brief Diffuse Fresnel reflectance Fdr(eta), the polynomial fit of Jensen et al. 2001 (Table 1 of
/// Chang et al. 2008). Valid on [kEtaMin, kEtaMax].
template <class T>
T diffuseFresnelReflectance(T eta) {
  return T(kFdrInvEta2) / (eta * eta) + T(kFdrInvEta) / eta + T(kFdrConst) + T(kFdrEta) * eta;
}

/// @brief Boundary mismatch term A = (1 + Fdr) / (1 - Fdr) of the dipole's extrapolated boundary.
template <class T>
T boundaryMismatch(T eta) {
  const T fdr = diffuseFresnelReflectance(eta);
  return (T(1) + fdr) / (T(1) - fdr);
}

}  // namespace lucent::optics
