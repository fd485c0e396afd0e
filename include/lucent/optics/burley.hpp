#pragma once
/// @file burley.hpp
/// @brief Christensen-Burley normalized diffusion (Christensen, Burley 2015, "Approximate
/// Reflectance Profiles for Efficient Subsurface Scattering", Pixar Technical Memo 15-04):
///   R(r) = A s (e^{-s r / l} + e^{-s r / (3 l)}) / (8 pi l r),
/// two exponentials whose total is exactly the surface albedo A, with the shape factor s fitted to
/// Monte Carlo as a function of A for a volume mean free path l (Eq. 5: searchlight, a beam
/// entering perpendicularly; Eq. 6: diffuse surface transmission, light entering from every
/// direction).
///
/// From measured coefficients: l = 1/sigma_t' and A = the total diffuse reflectance of photon beam
/// diffusion for the same medium (beam_diffusion.hpp), the most accurate total in this core
/// (docs/accuracy/profiles.md); the memo's fits were made against Monte Carlo with the same
/// meaning.
#include <algorithm>
#include <cmath>
#include <limits>

#include "constants.hpp"

namespace lucent::optics {

/// Which of the memo's fits of s(A).
enum class BurleyFit {
  Searchlight,     ///< Eq. 5: s = 1.85 - A + 7 |A - 0.8|^3
  DiffuseSurface,  ///< Eq. 6: s = 1.9 - A + 3.5 (A - 0.8)^2
};

inline double burleyShape(double albedo, BurleyFit fit) {
  const double a = albedo - 0.8;
  return fit == BurleyFit::Searchlight ? 1.85 - albedo + 7 * std::abs(a * a * a)
                                       : 1.9 - albedo + 3.5 * a * a;
}

template <class T>
struct BurleyChannel {
  T albedo = 0;  ///< A, the total
  T d = 1;       ///< l / s (mm)

  static BurleyChannel make(T albedo, T meanFreePath, BurleyFit fit) {
    BurleyChannel c;
    if (!(albedo > T(0)) || !(meanFreePath > T(0))) return c;
    c.albedo = albedo;
    c.d = meanFreePath / T(burleyShape(double(albedo), fit));
    return c;
  }

  bool scatters() const { return albedo > T(0); }
  /// R(r) in mm^-2; below 1e-4 d the 1/r singularity is held at its value there (that moves the
  /// total by 2.5e-5 of A), so a point sum stays finite.
  T rd(T r) const {
    if (!scatters() || !(r < std::numeric_limits<T>::infinity())) return T(0);
    const T rr = std::max(r, T(1e-4) * d);
    return albedo * (std::exp(-rr / d) + std::exp(-rr / (T(3) * d))) / (T(8 * kPi) * d * rr);
  }
  /// 2 pi int_0^rho R r dr = A (1 - e^{-rho/d} / 4 - 3 e^{-rho/(3d)} / 4), the unheld profile's.
  T cumulative(T rho) const {
    if (!scatters() || !(rho > T(0))) return T(0);
    if (!(rho < std::numeric_limits<T>::infinity())) return albedo;
    return albedo * (T(1) - T(0.25) * std::exp(-rho / d) - T(0.75) * std::exp(-rho / (T(3) * d)));
  }
  T total() const { return albedo; }
  T width() const { return d; }
  T reach() const { return T(12) * d; }
};

}  // namespace lucent::optics
