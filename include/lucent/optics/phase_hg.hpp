#pragma once
/// @file phase_hg.hpp
/// @brief Henyey-Greenstein phase function and the similarity relation sigma_s' = (1 - g) sigma_s.
#include <cmath>

#include "constants.hpp"

namespace lucent::optics {

/// @brief p(cos t) = (1/4pi) (1 - g^2) / (1 + g^2 - 2 g cos t)^{3/2}; normalised over the sphere.
/// @param cosTheta cosine of the angle between the propagation directions before and after scattering
/// @param g mean cosine in (-1, 1)
template <class T>
T phaseHG(T cosTheta, T g) {
  const T denom = T(1) + g * g - T(2) * g * cosTheta;
  return T(1.0 / (4.0 * kPi)) * (T(1) - g * g) / (denom * std::sqrt(denom));
}

/// @brief Samples cos t from the HG distribution with a uniform number u in [0,1).
/// Inverts the CDF in closed form; falls back to the isotropic inverse when |g| is tiny (0/0 otherwise).
template <class T>
T sampleCosThetaHG(T u, T g) {
  if (std::abs(g) < T(1e-3)) return T(1) - T(2) * u;
  const T s = (T(1) - g * g) / (T(1) - g + T(2) * g * u);
  const T c = (T(1) + g * g - s * s) / (T(2) * g);
  return c < T(-1) ? T(-1) : (c > T(1) ? T(1) : c);
}

/// @brief Reduced scattering coefficient by the similarity relation.
template <class T>
T reducedScattering(T sigmaS, T g) {
  return (T(1) - g) * sigmaS;
}

}  // namespace lucent::optics
