#pragma once
/// @file single_transport.hpp
/// @brief Single-scattering transport vectors (Wang, Tran, Luebke 2005, Sec. 3, Eq. 9-11): the
/// phase function factored into K terms p(w_in . w_out) ~ sum_k light_k(w_in) view_k(w_out), and
/// per surface point K transport functions over the environment's cube texels,
///   S_k(texel) = sum_t w(t) sigma_s sum_w' light_k(-w') eta^2 dw' [e^{-sigma_t s} Ft prod
///   Fr]_exits in texel,
/// along the negative normal at N deterministic depths t (the paper's view-independent path) and
/// over stratified directions w' inside, each followed through the boundary's reflections to where
/// it leaves (reference/single_scattering.hpp's forEachExit). A frame relights with
///   L = Ft(eta, w_o) / eta^2 sum_k view_k(w_o') (S_k . L),
/// w_o' the direction the light travels inside to leave towards the eye. An isotropic phase
/// function is the one term light = 1 / 4 pi, view = 1 (a diffuse vector).
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

#include "../optics/constants.hpp"
#include "../reference/single_scattering.hpp"
#include "../scene/cube_map.hpp"

namespace lucent::prt {

/// A phase function as K separable terms on a cube of `size` texels across, each indexed by the
/// texel of a direction of travel.
struct PhaseFactors {
  int size = 1;
  std::vector<std::vector<float>> light, view;  ///< K x 6 size^2

  std::size_t terms() const { return light.size(); }
  double lightAt(std::size_t k, const glm::dvec3& travel) const {
    return light[k][scene::cube::texelIndex(travel, size)];
  }
  double viewAt(std::size_t k, const glm::dvec3& travel) const {
    return view[k][scene::cube::texelIndex(travel, size)];
  }
  static PhaseFactors isotropic() {
    PhaseFactors p;
    p.light = {std::vector<float>(6, float(1 / (4 * optics::kPi)))};
    p.view = {std::vector<float>(6, 1.0f)};
    return p;
  }
};

struct SingleTransportSampling {
  int envSize = 16;       ///< the environment cube's texels across
  int depthSamples = 16;  ///< N per distinct channel coefficient
  int strata = 8;         ///< strata x 2 strata directions inside per depth
  double rayEpsilon = 1e-4;
};

/// The K transport functions of the point x (dense, 6 envSize^2 RGB each) into `out`.
inline void singleTransport(const reference::SingleScattering& term, const PhaseFactors& phase,
                            const glm::dvec3& x, const glm::dvec3& normal,
                            const glm::dvec3& faceNormal, const scene::RayCaster& caster,
                            const SingleTransportSampling& s,
                            std::vector<std::vector<glm::vec3>>& out) {
  const std::size_t texels = std::size_t(6) * s.envSize * s.envSize;
  out.assign(phase.terms(), std::vector<glm::vec3>(texels, glm::vec3(0)));
  const glm::dvec3 origin = x - faceNormal * s.rayEpsilon;
  const auto wall = caster.intersect(origin, -normal, 0, std::numeric_limits<double>::infinity());
  if (!wall) return;
  const reference::HomogeneousScattering& m = term.medium();
  const int k = std::max(1, s.strata);
  const double dOmega = 4 * optics::kPi / (2.0 * k * k);
  for (const reference::DepthSample& d :
       reference::depthSamples(m.sigmaT, wall->t, s.depthSamples)) {
    const glm::dvec3 at = origin - normal * d.t;
    const glm::dvec3 scale = d.weight * m.sigmaS * (m.eta * m.eta * dOmega);
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < 2 * k; ++j) {
        const double z = 1 - 2 * (i + 0.5) / k, r = std::sqrt(std::max(0.0, 1 - z * z));
        const double phi = optics::kPi * (j + 0.5) / k;
        const glm::dvec3 w(r * std::cos(phi), r * std::sin(phi), z);
        term.forEachExit(at, w, [&](const glm::dvec3& outside, const glm::dvec3& weight) {
          const std::size_t texel = scene::cube::texelIndex(outside, s.envSize);
          for (std::size_t t = 0; t < phase.terms(); ++t)
            out[t][texel] += glm::vec3(scale * weight * phase.lightAt(t, -w));
        });
      }
  }
}

}  // namespace lucent::prt
