#pragma once
/// @file diffusion_sphere.hpp
/// @brief The diffusion equation's exact solution in a homogeneous sphere under uniform illumination, the
/// analytic check of the QuadGraph solver: div(kappa grad phi) = mu phi inside (Wang et al. 2010 Eq. 1)
/// gives phi(r) = C sinh(k r) / r, k = sqrt(mu / kappa), and the Robin condition (Eq. 2)
/// phi(R) + 2 A kappa phi'(R) = 4 q / (1 - Fdr) fixes C. mu = 0 (Laplace) gives phi = 4 q / (1 - Fdr).
#include <cmath>

#include "../optics/diffusion_boundary.hpp"

namespace lucent::reference {

class DiffusionSphere {
 public:
  /// @param radius mm; @param sigmaA, sigmaSPrime mm^-1; @param q transmitted irradiance at the surface.
  DiffusionSphere(double radius, double sigmaA, double sigmaSPrime, double eta, double q)
      : mR(radius), mKappa(1.0 / (3.0 * (sigmaA + sigmaSPrime))), mK(std::sqrt(sigmaA / mKappa)),
        mA(optics::boundaryMismatch(eta)), mFdr(optics::diffuseFresnelReflectance(eta)),
        mQ(optics::diffusionBoundarySource(q, mFdr)), mIrradiance(q) {
    // phi(r) = Q f(r) / (f(R) + 2 A kappa f'(R)) with f(r) = sinh(kr) / (kr) (-> 1 as k -> 0, so mu = 0 is
    // the same formula), all scaled by e^{-kR} so that large kR (dense media, big spheres) cannot overflow.
    const double x = mK * mR, e2 = std::exp(-2 * x);
    const double f = x > 1e-4 ? 0.5 * (1 - e2) / x : std::exp(-x) * (1 + x * x / 6);
    const double df = x > 1e-4 ? 0.5 * (1 + e2) / mR - 0.5 * (1 - e2) / (x * mR)  // e^{-kR}(cosh/R - sinh/(kR^2))
                               : std::exp(-x) * mK * x / 3;
    mScaledC = mQ / (f + 2 * mA * mKappa * df);
  }

  /// phi at distance r from the centre.
  double flux(double r) const {
    const double x = mK * r;
    if (x < 1e-4) return mScaledC * std::exp(-mK * mR) * (1 + x * x / 6);
    return mScaledC * (std::exp(mK * (r - mR)) - std::exp(-mK * (r + mR))) / (2 * x);
  }

  /// B at the surface (Eq. 7 with the transmitted fraction), the radiosity in L = Ft B / pi.
  double surfaceRadiosity() const { return optics::diffusionBoundaryRadiosity(flux(mR), mIrradiance, mFdr); }
  double kappa() const { return mKappa; }
  double k() const { return mK; }

 private:
  double mR, mKappa, mK, mA, mFdr, mQ, mIrradiance, mScaledC = 0;
};

}  // namespace lucent::reference
