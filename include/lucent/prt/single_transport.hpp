#pragma once
/// @file single_transport.hpp
/// @brief Single-scattering transport vectors (Wang, Tran, Luebke 2005, Sec. 3, Eq. 9-11): the
/// phase function factored into K terms p(w_in . w_out) ~ sum_k light_k(w_in) view_k(w_out), and
/// per surface point K transport functions over the environment's cube texels,
///   S_k(texel) = sum_t w(t) sigma_s light_k(w_i') e^{-sigma_t s_i'} Ft cos(theta_i)/cos(theta_i')
///   dOmega,
/// along the negative normal at N deterministic depths t drawn by the luminance of sigma_t (the
/// paper's view-independent path and distances), the light of each texel's direction w entering by
/// Jensen 2001's refracted straight line (reference/single_scattering.hpp's enterStraight; the
/// paper rasterised the same depths and normals), w_i' its direction of travel inside. Every texel
/// is reached, so a one-texel sun gives no sampling blotches. A frame relights with
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
  int size = 8;           ///< texels across of the cube it is computed on (upsampled to envSize)
  int depthSamples = 16;  ///< N, drawn by sigma_t's luminance
  double rayEpsilon = 1e-4;
};

/// A transport function on a cube `coarse` across spread onto one `fine` across (a multiple): each
/// texel's value shared among the texels inside it by their solid angles, so every integral against
/// a light constant on coarse texels is kept.
inline std::vector<glm::vec3> upsampleTransport(const std::vector<glm::vec3>& values, int coarse,
                                                int fine) {
  if (fine == coarse) return values;
  const int ratio = fine / coarse;
  std::vector<glm::vec3> out(std::size_t(6) * fine * fine);
  for (int face = 0; face < 6; ++face)
    for (int row = 0; row < fine; ++row)
      for (int col = 0; col < fine; ++col) {
        const int r = row / ratio, c = col / ratio;
        const double share = scene::cube::texelSolidAngle(row, col, fine) /
                             scene::cube::texelSolidAngle(r, c, coarse);
        out[(std::size_t(face) * fine + row) * fine + col] =
            values[(std::size_t(face) * coarse + r) * coarse + c] * float(share);
      }
  return out;
}

/// The K transport functions of the point x (dense, 6 envSize^2 RGB each) into `out`, computed on
/// the cube `s.size` across (at most envSize, a power of two) and spread onto envSize.
inline void singleTransport(const reference::SingleScattering& term, const PhaseFactors& phase,
                            const glm::dvec3& x, const glm::dvec3& normal,
                            const glm::dvec3& faceNormal, const scene::RayCaster& caster,
                            const SingleTransportSampling& s,
                            std::vector<std::vector<glm::vec3>>& out) {
  const int size = std::min(s.size, s.envSize);
  const std::size_t texels = std::size_t(6) * size * size;
  out.assign(phase.terms(), std::vector<glm::vec3>(texels, glm::vec3(0)));
  struct Spread {  // the coarse functions onto the environment's cube, however this returns
    std::vector<std::vector<glm::vec3>>& out;
    int size, envSize;
    ~Spread() {
      for (auto& k : out) k = upsampleTransport(k, size, envSize);
    }
  } spread{out, size, s.envSize};
  const glm::dvec3 origin = x - faceNormal * s.rayEpsilon;
  const auto wall = caster.intersect(origin, -normal, 0, std::numeric_limits<double>::infinity());
  if (!wall) return;
  const reference::HomogeneousScattering& m = term.medium();
  const double luminance = 0.2126 * m.sigmaT.x + 0.7152 * m.sigmaT.y + 0.0722 * m.sigmaT.z;
  for (const reference::DepthSample& d :
       reference::depthSamples(m.sigmaT, wall->t, s.depthSamples, {luminance})) {
    const glm::dvec3 at = origin - normal * d.t;
    const glm::dvec3 scale = d.weight * m.sigmaS;
    for (std::size_t texel = 0; texel < texels; ++texel) {
      const auto entry = term.enterStraight(at, scene::cube::texelCentre(texel, size),
                                            std::numeric_limits<double>::infinity());
      if (!entry) continue;
      const std::size_t inFace = texel % (std::size_t(size) * size);
      const double dOmega =
          scene::cube::texelSolidAngle(int(inFace / size), int(inFace % size), size);
      const glm::dvec3 light = scale * entry->attenuation * (entry->transmitted * dOmega);
      for (std::size_t k = 0; k < phase.terms(); ++k)
        out[k][texel] += glm::vec3(light * phase.lightAt(k, entry->travel));
    }
  }
}

}  // namespace lucent::prt
