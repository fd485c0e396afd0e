#pragma once
/// @file tet_mesh.hpp
/// @brief A tetrahedral mesh (mm), as the QuadGraph diffusion solver consumes it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace lucent::scene {

struct TetMesh {
  std::vector<glm::dvec3> positions;
  std::vector<glm::uvec4> tets;  ///< positively oriented: volume() > 0, or within flatTolerance for a sliver
  /// The boundary faces (vertex triples) and, for each, the input surface triangle it lies on. A
  /// boundary face equals its source triangle when the surface was preserved, and is a piece of it
  /// otherwise.
  std::vector<glm::uvec3> boundaryFaces;
  std::vector<std::uint32_t> boundarySource;

  double volume(std::size_t t) const {
    const glm::dvec3 a = positions[tets[t].x], b = positions[tets[t].y], c = positions[tets[t].z],
                     d = positions[tets[t].w];
    return glm::dot(b - a, glm::cross(c - a, d - a)) / 6.0;
  }
  /// Inside out: a volume below zero by more than double rounding of the tet's size. A tet within
  /// that rounding is a sliver a mesher's exact predicates oriented; its computed volume may be 0
  /// or -1e-19.
  bool inverted(std::size_t t) const {
    const double v = volume(t);
    return !std::isfinite(v) || v < -flatTolerance(positions, tets[t]);
  }
  /// Relative volume (to the longest edge cubed) under which a tet counts as flat, not inverted.
  static constexpr double kFlatVolume = 1e-12;
  /// The longest of the tet's six edges (mm).
  static double longestEdge(const std::vector<glm::dvec3>& points, const glm::uvec4& tet) {
    double longest = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        longest = std::max(longest, glm::length(points[tet[i]] - points[tet[j]]));
    return longest;
  }
  /// The volume a flat tet with these corners can show by rounding: kFlatVolume x its longest
  /// edge^3.
  static double flatTolerance(const std::vector<glm::dvec3>& points, const glm::uvec4& tet) {
    const double longest = longestEdge(points, tet);
    return kFlatVolume * longest * longest * longest;
  }
  double totalVolume() const {
    double v = 0;
    for (std::size_t t = 0; t < tets.size(); ++t) v += volume(t);
    return v;
  }
};

}  // namespace lucent::scene
