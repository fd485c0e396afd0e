#pragma once
/// @file constants.hpp
/// @brief The numeric constants of the optics core and of the filter patterns its GPU twins share;
/// the single source for C++ and (generated, cmake/embed_glsl.cmake) GLSL.

namespace lucent::optics {

/// pi to double precision; use `T(kPi)` in templated code.
inline constexpr double kPi = 3.14159265358979323846;

/// Coefficients of the polynomial fit of the diffuse Fresnel reflectance
/// Fdr(eta) = c0/eta^2 + c1/eta + c2 + c3*eta (Jensen et al. 2001, Eq. 5; Egan and Hilgeman's fit).
inline constexpr double kFdrInvEta2 = -1.440;
inline constexpr double kFdrInvEta = 0.710;
inline constexpr double kFdrConst = 0.668;
inline constexpr double kFdrEta = 0.0636;

/// The range of relative indices of refraction the Fdr fit is used on. Below 1 the fit is a
/// different polynomial; above 3 Fdr approaches 1 and A = (1+Fdr)/(1-Fdr) loses all precision.
inline constexpr double kEtaMin = 1.0;
inline constexpr double kEtaMax = 3.0;

/// The turn between consecutive rings of a ring filter's taps, the golden angle 2 pi (2 - phi)
/// (no aligned spokes; atlas/translucent_shadow_map.hpp).
inline constexpr double kGoldenAngle = 2.399963229728653;

/// The spatial hash that turns a point's tap pattern (voxel/tau_lut_radiance.hpp): the primes of
/// Teschner et al. 2003 on the quantised position, then a 32-bit integer finaliser.
inline constexpr unsigned kTurnHashX = 73856093u;
inline constexpr unsigned kTurnHashY = 19349663u;
inline constexpr unsigned kTurnHashZ = 83492791u;
inline constexpr unsigned kTurnHashMix = 0x45d9f3bu;

}  // namespace lucent::optics
