#pragma once
/// @file participating_media.hpp
/// @brief What the path tracer sees: media (absorption, scattering, HG g, index of refraction, an
/// optional density field) and closed surfaces that separate them. Every triangle names the medium
/// behind its counter-clockwise face (inside) and in front of it (outside), so nested objects,
/// cavities and inclusions of another material are one triangle soup; medium 0 is the surrounding
/// vacuum (eta 1).
#include <algorithm>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "../optics/materials.hpp"
#include "../scene/mesh.hpp"

namespace lucent::reference {

struct Medium {
  std::string name = "vacuum";
  glm::dvec3 sigmaA{0};  ///< mm^-1 at density 1
  glm::dvec3 sigmaS{0};  ///< mm^-1 at density 1 (not reduced: the phase function carries g)
  double g = 0;          ///< Henyey-Greenstein mean cosine
  double eta = 1;        ///< absolute index of refraction
  /// Density multiplier of both coefficients; empty = homogeneous. Must not exceed `maxDensity`,
  /// the majorant of delta and ratio tracking (a larger value is clamped and counted as a
  /// violation).
  std::function<double(const glm::dvec3&)> density;
  double maxDensity = 1;
  /// Per-point (sigma_a, sigma_s) replacing the constants and the density (a scan through a
  /// transfer function); `maxSigmaT` bounds max_c sigma_t,c over it (the tracking majorant).
  std::function<std::pair<glm::dvec3, glm::dvec3>(const glm::dvec3&)> coefficients;
  double maxSigmaT = 0;

  bool homogeneous() const { return !density && !coefficients; }
  glm::dvec3 sigmaT() const { return sigmaA + sigmaS; }
  bool vacuum() const { return homogeneous() && sigmaT() == glm::dvec3(0); }
};

/// A measured material as a medium: sigma_s = sigma_s' / (1 - g) keeps the reduced coefficient the
/// dipole uses (similarity relation), so both see the same material whatever g is.
inline Medium mediumFromMaterial(const optics::Material& m, double g = 0) {
  if (!(g > -1 && g < 1)) throw std::invalid_argument("HG g must lie in (-1, 1)");
  Medium out;
  out.name = m.name;
  out.sigmaA = glm::dvec3(m.sigmaA);
  out.sigmaS = glm::dvec3(m.sigmaSPrime) / (1 - g);
  out.g = g;
  out.eta = m.eta;
  return out;
}

struct MediumScene {
  std::vector<Medium> media{Medium{}};  ///< media[0] is the surroundings
  scene::TriangleMesh mesh;             ///< every body's triangles, for one ray caster
  std::vector<std::uint32_t> inside,
      outside;  ///< per triangle: medium behind / in front of the face

  std::uint32_t addMedium(Medium m) {
    media.push_back(std::move(m));
    return std::uint32_t(media.size() - 1);
  }
  /// Appends a closed, outward-oriented surface with `insideMedium` within it and `outsideMedium`
  /// around it (for a cavity: inside = 0, outside = the material that holds it).
  void addBody(const scene::TriangleMesh& body, std::uint32_t insideMedium,
               std::uint32_t outsideMedium) {
    if (insideMedium >= media.size() || outsideMedium >= media.size())
      throw std::invalid_argument("addBody: unknown medium id");
    const auto base = std::uint32_t(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), body.positions.begin(), body.positions.end());
    for (const auto& t : body.triangles) mesh.triangles.push_back(t + base);
    inside.insert(inside.end(), body.triangles.size(), insideMedium);
    outside.insert(outside.end(), body.triangles.size(), outsideMedium);
  }
  /// True when no interface refracts: every medium has the index of the surroundings.
  bool indexMatched() const {
    return std::all_of(media.begin(), media.end(),
                       [&](const Medium& m) { return m.eta == media[0].eta; });
  }
};

}  // namespace lucent::reference
