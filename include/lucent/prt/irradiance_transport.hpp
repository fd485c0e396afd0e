#pragma once
/// @file irradiance_transport.hpp
/// @brief The irradiance transport function of a surface point over a cube map's texels (Wang,
/// Tran, Luebke 2005, Sec. 3, Eq. 8): E(k) = int over texel k of V(x, w) Ft(eta, n.w) max(n.w, 0)
/// dw, so that the irradiance through the boundary under any environment constant on texels is E =
/// sum_k E(k) L(k). Visibility by ray casting (the paper rasterised a stencil); each texel is cut
/// into sub x sub face rectangles, each with its exact solid angle and one ray through its centre
/// (the paper's 2 x 2 supersampling is sub = 2).
#include <cstddef>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

#include "../optics/fresnel.hpp"
#include "../scene/cube_map.hpp"
#include "../scene/ray_caster.hpp"
#include "haar.hpp"
#include "sparse_vector.hpp"

namespace lucent::prt {

struct TransportSampling {
  int size = 16;             ///< cube face texels across
  int subdivision = 1;       ///< rays per texel side
  double eta = 1.3;          ///< the boundary's relative index
  double rayEpsilon = 1e-4;  ///< mm off the surface
};

/// E(k) for every texel k of the cube, into `out` (6 size^2 values, overwritten).
inline void irradianceTransport(const glm::dvec3& x, const glm::dvec3& normal,
                                const glm::dvec3& faceNormal, const scene::RayCaster& caster,
                                const TransportSampling& s, std::vector<float>& out) {
  const int n = s.size, sub = std::max(1, s.subdivision);
  out.assign(std::size_t(scene::cube::kFaces) * n * n, 0.0f);
  const glm::dvec3 origin = x + faceNormal * s.rayEpsilon;
  const double cell = 2.0 / (double(n) * sub);
  for (int face = 0; face < scene::cube::kFaces; ++face)
    for (int row = 0; row < n * sub; ++row)
      for (int col = 0; col < n * sub; ++col) {
        const double s0 = -1 + col * cell, t0 = -1 + row * cell;
        const glm::dvec3 w =
            glm::normalize(scene::cube::faceDirection(face, s0 + 0.5 * cell, t0 + 0.5 * cell));
        const double cosN = glm::dot(normal, w);
        if (cosN <= 0 || glm::dot(faceNormal, w) <= 0) continue;
        if (caster.occluded(origin, w, 0, std::numeric_limits<double>::infinity())) continue;
        const double dOmega = scene::cube::rectangleSolidAngle(s0, s0 + cell, t0, t0 + cell);
        out[(std::size_t(face) * n + row / sub) * n + col / sub] +=
            float(optics::fresnelTransmittance(cosN, s.eta) * cosN * dOmega);
      }
}

/// The Haar coefficients of a cube of texel values (transformed in place) with the `terms` largest
/// kept (0 keeps all).
template <class V>
Sparse<V> compress(std::vector<V>& texels, int size, std::size_t terms) {
  haarForwardCube(texels, size);
  return keepLargest(texels, size, terms == 0 ? texels.size() : terms);
}

}  // namespace lucent::prt
