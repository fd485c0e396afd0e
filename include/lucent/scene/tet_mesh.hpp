#pragma once
/// @file tet_mesh.hpp
/// @brief A tetrahedral mesh (mm), as the QuadGraph diffusion solver consumes it.
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace lucent::scene {

struct TetMesh {
  std::vector<glm::dvec3> positions;
  std::vector<glm::uvec4> tets;  ///< positively oriented: volume() > 0
  /// The boundary faces (vertex triples) and, for each, the input surface triangle it lies on. A boundary
  /// face equals its source triangle when the surface was preserved, and is a piece of it otherwise.
  std::vector<glm::uvec3> boundaryFaces;
  std::vector<std::uint32_t> boundarySource;

  double volume(std::size_t t) const {
    const glm::dvec3 a = positions[tets[t].x], b = positions[tets[t].y], c = positions[tets[t].z], d = positions[tets[t].w];
    return glm::dot(b - a, glm::cross(c - a, d - a)) / 6.0;
  }
  double totalVolume() const {
    double v = 0;
    for (std::size_t t = 0; t < tets.size(); ++t) v += volume(t);
    return v;
  }
};

}  // namespace lucent::scene
