#pragma once
/// @file vertex_radiosity.hpp
/// @brief Shading from radiosity stored at mesh vertices (per-vertex TSIS, QuadGraph's surface nodes):
/// B interpolated over the hit triangle, L = Ft(cos) B / pi, the dipole truth's convention.
#include <vector>

#include "../optics/constants.hpp"
#include "../optics/fresnel.hpp"
#include "dipole_truth.hpp"

namespace lucent::reference {

/// B at a hit, interpolated from the hit triangle's vertices with the hit's barycentrics.
inline glm::dvec3 interpolateAtHit(const scene::TriangleMesh& mesh, const std::vector<glm::dvec3>& vertexValues,
                                   const ShadingPoint& hit) {
  const auto& tri = mesh.triangles[hit.triangle];
  return (1 - hit.u - hit.v) * vertexValues[tri.x] + hit.u * vertexValues[tri.y] + hit.v * vertexValues[tri.z];
}

/// An evaluator for renderTruth: given radiosity per vertex, exact Fresnel transmittance on the way out.
class VertexRadiosity {
 public:
  VertexRadiosity(const scene::TriangleMesh& mesh, std::vector<glm::dvec3> radiosity, double eta)
      : mMesh(mesh), mB(std::move(radiosity)), mEta(eta) {}
  glm::dvec3 radiance(const ShadingPoint& hit) const {
    return interpolateAtHit(mMesh, mB, hit) * (optics::fresnelTransmittance(hit.cosOut, mEta) / optics::kPi);
  }

 private:
  const scene::TriangleMesh& mMesh;
  std::vector<glm::dvec3> mB;
  double mEta;
};

}  // namespace lucent::reference
