#pragma once
/// @file diffusion_boundary.hpp
/// @brief What the diffusion approximation's boundary takes in and gives out, in one place for the QuadGraph
/// solver and its analytic sphere (Wang et al. 2010 Eq. 2 and 7).
///
/// At a boundary with internal diffuse reflectance Fdr, the inward partial current phi/4 + (kappa/2) dphi/dn
/// (n the inward normal) is q (the transmitted incident irradiance) plus Fdr times the outward partial current
/// J- = phi/4 - (kappa/2) dphi/dn. Eliminating dphi/dn gives the Robin condition of Eq. 2,
/// phi - 2 A kappa dphi/dn = 4 q / (1 - Fdr), and J- = (phi - 2 q) / (2 (1 + Fdr)): the bracket of Eq. 7.
/// Only (1 - Fdr) J- leaves; that transmitted exitance is the radiosity B in L = Ft(w_o) B / pi, the dipole
/// truth's convention. Eq. 7 as printed applies Ft to J- itself, which at zero absorption sends out
/// 1 / (1 - Fdr) times the light that came in (1.80x at eta 1.3); the volumetric path tracer measures
/// 1.84x for that formula and 1.02x for this one on a 30 mm spectralon sphere (docs/accuracy/quadgraph.md).
#include "fresnel.hpp"

namespace lucent::optics {

/// Right-hand side of the Robin condition (Eq. 2): Q = 4 q / (1 - Fdr).
template <class T>
T diffusionBoundarySource(T transmittedIrradiance, T fdr) {
  return T(4) * transmittedIrradiance / (T(1) - fdr);
}

/// Radiosity leaving the boundary, B = (1 - Fdr) (phi - 2 q) / (2 (1 + Fdr)), from the fluence phi there and
/// the transmitted irradiance q. Zero absorption makes it equal q (everything that enters leaves).
template <class T>
T diffusionBoundaryRadiosity(T fluence, T transmittedIrradiance, T fdr) {
  return (T(1) - fdr) * (fluence - T(2) * transmittedIrradiance) / (T(2) * (T(1) + fdr));
}

}  // namespace lucent::optics
