#pragma once
/// @file validity.hpp
/// @brief The scales a technique's approximations hold at, measured on a scene: the object's size
/// against the material's transport mean free path l_u = 1/sigma_t' and diffusion length
/// 1/sigma_tr, and a discretisation's step (atlas texel, shadow-map texel, mesh edge) against
/// them. A technique states its range with these (Technique::validity) and refuses a scene outside
/// it, with the reason and the fix, before any work; tests/integration/test_hard_cases.cpp holds
/// every technique to it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include <glm/geometric.hpp>

#include "../optics/materials.hpp"
#include "../scene/mesh.hpp"
#include "../util/number_text.hpp"

namespace lucent::technique {

/// Lengths of the channels that scatter (a channel with sigma_s' = 0 has no diffuse term at all).
struct OpticalScales {
  bool scatters = false;
  double longestMeanFreePath = 0;  ///< max l_u: the most transparent channel
  double shortestMeanFreePath = std::numeric_limits<double>::infinity();  ///< min l_u: sharpest Rd
  double shortestDiffusionLength = std::numeric_limits<double>::infinity();  ///< min 1/sigma_tr
  /// The length Rd falls off over: its peak's width l_u, or 1/sigma_tr where absorption cuts the
  /// tail shorter (low albedo).
  double rdWidth() const { return std::min(shortestMeanFreePath, shortestDiffusionLength); }
};

inline OpticalScales opticalScales(const optics::Material& m) {
  OpticalScales s;
  for (int c = 0; c < 3; ++c) {
    if (!(m.sigmaSPrime[c] > 0)) continue;
    s.scatters = true;
    const double sigmaTPrime = m.sigmaA[c] + m.sigmaSPrime[c];
    const double sigmaTr = std::sqrt(3 * m.sigmaA[c] * sigmaTPrime);
    s.longestMeanFreePath = std::max(s.longestMeanFreePath, 1 / sigmaTPrime);
    s.shortestMeanFreePath = std::min(s.shortestMeanFreePath, 1 / sigmaTPrime);
    if (sigmaTr > 0) s.shortestDiffusionLength = std::min(s.shortestDiffusionLength, 1 / sigmaTr);
  }
  return s;
}

using util::numberText;
using util::valueText;
inline std::string lengthText(double mm) { return numberText(mm) + " mm"; }

namespace validity {

/// Diffusion (the dipole, a diffusion solve) needs an optically thick object: at least
/// kMinMeanFreePaths transport mean free paths across its bounding-box diagonal in every channel
/// that scatters. Below it light mostly passes through or scatters once. "" when it holds.
inline constexpr double kMinMeanFreePaths = 3;
/// The range opticallyThick checks, in words.
inline std::string thickRange() {
  return "at least " + std::to_string(int(kMinMeanFreePaths)) + " transport mean free paths across";
}
inline std::string opticallyThick(const scene::TriangleMesh& mesh, const optics::Material& m) {
  const OpticalScales s = opticalScales(m);
  const double diagonal = mesh.bounds().diagonal();
  if (!s.scatters || diagonal >= kMinMeanFreePaths * s.longestMeanFreePath) return "";
  return "the object (" + lengthText(diagonal) + " across) is " +
         numberText(diagonal / s.longestMeanFreePath) + " transport mean free paths across (" +
         lengthText(s.longestMeanFreePath) + " each); diffusion needs at least " +
         std::to_string(int(kMinMeanFreePaths)) +
         ": use a technique that simulates single scattering (pathtrace) or a larger --size-mm";
}

/// A discretisation step must resolve Rd: at most kMaxStepInRdWidths of the length Rd falls off
/// over (OpticalScales::rdWidth). "" when it holds.
inline constexpr double kMaxStepInRdWidths = 2;
inline std::string resolvesRd(double step, const std::string& what, const optics::Material& m,
                              const std::string& fix) {
  const OpticalScales s = opticalScales(m);
  if (!s.scatters || step <= kMaxStepInRdWidths * s.rdWidth()) return "";
  return what + " is " + lengthText(step) + ", more than " +
         std::to_string(int(kMaxStepInRdWidths)) + " widths of Rd (" + lengthText(s.rdWidth()) +
         ", the shorter of the mean free path and 1/sigma_tr): Rd is not resolved and the image "
         "comes out too dark; " +
         fix;
}

}  // namespace validity

/// Total area of a mesh (mm^2).
inline double surfaceArea(const scene::TriangleMesh& mesh) {
  double a = 0;
  for (const auto& t : mesh.triangles)
    a += 0.5 * glm::length(glm::cross(glm::dvec3(mesh.positions[t.y] - mesh.positions[t.x]),
                                      glm::dvec3(mesh.positions[t.z] - mesh.positions[t.x])));
  return a;
}

/// Mean edge length of a mesh (mm), each triangle's three edges.
inline double meanEdgeLength(const scene::TriangleMesh& mesh) {
  double sum = 0;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      sum += glm::length(glm::dvec3(mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]]));
  return mesh.triangles.empty() ? 0 : sum / (3.0 * double(mesh.triangles.size()));
}

}  // namespace lucent::technique
