#pragma once
/// @file constants.hpp
/// @brief The numeric constants of the optics core; the single source for C++ and (generated) GLSL.

namespace lucent::optics {

/// pi to double precision; use `T(kPi)` in templated code.
inline constexpr double kPi = 3.14159265358979323846;

/// Coefficients of the polynomial fit of the diffuse Fresnel reflectance
/// Fdr(eta) = c0/eta^2 + c1/eta + c2 + c3*eta (Jensen et al. 2001, Eq. 5; Egan and Hilgeman's fit).
inline constexpr double kFdrInvEta2 = -1.440;
inline constexpr double kFdrInvEta = 0.710;
inline constexpr double kFdrConst = 0.668;
inline constexpr double kFdrEta = 0.0636;

/// The range of relative indices of refraction the Fdr fit is used on. Below 1 the fit is a different
/// polynomial; above 3 Fdr approaches 1 and A = (1+Fdr)/(1-Fdr) loses all precision.
inline constexpr double kEtaMin = 1.0;
inline constexpr double kEtaMax = 3.0;

}  // namespace lucent::optics
