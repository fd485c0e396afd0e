#pragma once
/// @file surface_mapping.hpp
/// @brief Between a QuadGraph's surface nodes and the input triangle mesh: where each node sits on its
/// source triangle (to evaluate irradiance there), and node values spread to the mesh's vertices for
/// display (Wang et al. 2010 Sec. 5.3 renders a triangulation of the nodes; mapping to the input mesh
/// keeps the user's geometry and normals).
#include <vector>

#include <glm/geometric.hpp>

#include "../scene/mesh.hpp"
#include "quad_graph.hpp"

namespace lucent::quadgraph {

/// Barycentrics of each surface node in its source triangle (projected and clamped onto it).
/// Throws std::invalid_argument if a node has no source triangle (a tet mesh without boundary sources).
inline std::vector<glm::dvec3> sourceBarycentrics(const QuadGraph& g, const scene::TriangleMesh& mesh) {
  std::vector<glm::dvec3> out(g.surfaceCount());
  for (std::size_t s = 0; s < g.surfaceCount(); ++s) {
    const std::uint32_t t = g.surfaceSource[s];
    if (t == kNoSource || t >= mesh.triangles.size())
      throw std::invalid_argument("QuadGraph: surface node " + std::to_string(s) + " has no source triangle");
    const auto& tri = mesh.triangles[t];
    const glm::dvec3 a(mesh.positions[tri.x]), b(mesh.positions[tri.y]), c(mesh.positions[tri.z]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double nn = glm::dot(n, n);
    const glm::dvec3 p = g.positions[g.innerCount() + s];
    glm::dvec3 w(glm::dot(glm::cross(c - b, p - b), n), glm::dot(glm::cross(a - c, p - c), n),
                 glm::dot(glm::cross(b - a, p - a), n));
    w = glm::max(w / (nn > 0 ? nn : 1.0), glm::dvec3(0));
    const double sum = w.x + w.y + w.z;
    out[s] = sum > 0 ? w / sum : glm::dvec3(1.0 / 3.0);
  }
  return out;
}

/// Per-vertex values: each node's value spread to its source triangle's vertices with weight
/// (barycentric x face area), normalised per vertex (a partition of unity, so constants stay constant).
inline std::vector<double> nodesToVertices(const QuadGraph& g, const scene::TriangleMesh& mesh,
                                           const std::vector<glm::dvec3>& barycentrics,
                                           const std::vector<double>& nodeValues) {
  std::vector<double> sum(mesh.positions.size(), 0.0), weight(mesh.positions.size(), 0.0);
  for (std::size_t s = 0; s < g.surfaceCount(); ++s) {
    const auto& tri = mesh.triangles[g.surfaceSource[s]];
    const double area = g.faceArea[4 * g.surfaceInner[s] + g.surfaceSlot[s]];
    for (int k = 0; k < 3; ++k) {
      const double w = barycentrics[s][k] * area;
      sum[tri[k]] += w * nodeValues[s];
      weight[tri[k]] += w;
    }
  }
  for (std::size_t v = 0; v < sum.size(); ++v) sum[v] = weight[v] > 0 ? sum[v] / weight[v] : 0.0;
  return sum;
}

}  // namespace lucent::quadgraph
