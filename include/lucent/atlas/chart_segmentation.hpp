#pragma once
/// @file chart_segmentation.hpp
/// @brief Cuts a closed mesh into charts that project onto a plane without flipping: each chart grows
/// over edge-adjacent triangles whose normals stay within a cone around the seed's normal. Projected
/// along the cone axis, every triangle keeps its orientation and at least cos(angle) of its area, so the
/// area ratio A_S/A_T of Chang et al. 2008 Eq. 6 stays within [1, 1/cos(angle)].
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <queue>
#include <unordered_map>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "../scene/mesh.hpp"
#include "../util/basis.hpp"

namespace lucent::atlas {

struct ChartSet {
  std::vector<int> chartOfTriangle;     ///< -1: degenerate triangle (no area, in no chart)
  std::vector<glm::dvec3> axis;         ///< projection direction of each chart (unit)
  int count() const { return int(axis.size()); }
};

/// Edge-adjacent triangles of each triangle (up to three per edge on non-manifold input).
inline std::vector<std::vector<std::uint32_t>> triangleNeighbours(const scene::TriangleMesh& mesh) {
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> byEdge;
  byEdge.reserve(mesh.triangles.size() * 3);
  auto key = [](std::uint32_t a, std::uint32_t b) {
    return (std::uint64_t(std::min(a, b)) << 32) | std::uint64_t(std::max(a, b));
  };
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) byEdge[key(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3])].push_back(t);
  std::vector<std::vector<std::uint32_t>> out(mesh.triangles.size());
  for (const auto& [edge, tris] : byEdge)
    for (std::uint32_t a : tris)
      for (std::uint32_t b : tris)
        if (a != b) out[a].push_back(b);
  return out;
}

/// @param maxAngleOfTriangle the cone half-angle (radians) each triangle may deviate from its chart's
/// axis; per triangle so that charts found to overlap can be re-cut finer (texture_atlas.hpp).
inline ChartSet segmentCharts(const scene::TriangleMesh& mesh, const std::vector<double>& maxAngleOfTriangle,
                              const std::vector<std::vector<std::uint32_t>>& neighbours) {
  const std::size_t n = mesh.triangles.size();
  ChartSet charts;
  charts.chartOfTriangle.assign(n, -1);
  std::vector<glm::dvec3> normal(n);
  std::vector<double> area(n);
  for (std::size_t t = 0; t < n; ++t) {
    const glm::dvec3 a = mesh.areaVector(t);
    area[t] = glm::length(a);
    normal[t] = area[t] > 0 ? a / area[t] : glm::dvec3(0);
  }
  // Seeds in order of decreasing area: large flat regions become large charts.
  std::vector<std::uint32_t> order(n);
  for (std::uint32_t t = 0; t < n; ++t) order[t] = t;
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return area[a] > area[b]; });
  std::queue<std::uint32_t> frontier;
  for (std::uint32_t seed : order) {
    if (charts.chartOfTriangle[seed] >= 0 || !(area[seed] > 0)) continue;
    const int id = charts.count();
    const glm::dvec3 axis = normal[seed];
    charts.axis.push_back(axis);
    charts.chartOfTriangle[seed] = id;
    frontier.push(seed);
    while (!frontier.empty()) {
      const std::uint32_t t = frontier.front();
      frontier.pop();
      for (std::uint32_t nb : neighbours[t]) {
        if (charts.chartOfTriangle[nb] >= 0 || !(area[nb] > 0)) continue;
        const double limit = std::min(maxAngleOfTriangle[nb], maxAngleOfTriangle[seed]);
        if (glm::dot(normal[nb], axis) < std::cos(limit)) continue;
        charts.chartOfTriangle[nb] = id;
        frontier.push(nb);
      }
    }
  }
  return charts;
}

/// Orthographic projection of a point onto the plane normal to `axis`, in mm, right-handed so that a
/// triangle facing along the axis keeps its counter-clockwise order.
inline glm::dvec2 projectToChart(const glm::dvec3& p, const glm::dvec3& axis) {
  glm::dvec3 t, b;
  util::orthonormalBasis(axis, t, b);
  return {glm::dot(p, t), glm::dot(p, b)};
}

}  // namespace lucent::atlas
