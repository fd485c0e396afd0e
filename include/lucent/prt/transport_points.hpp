#pragma once
/// @file transport_points.hpp
/// @brief Where the per-vertex transport vectors (Wang et al. 2005, Eq. 6-7) are computed: at most
/// a budget of the mesh's vertices, picked one per grid cell and normal direction, every vertex
/// then interpolating the relit points (Shepard weights from the nearest that face its way).
/// Multiple scattering is blurred over the diffusion profile's width, so transport sampled no
/// coarser than that width loses little, while a scanned mesh's vertex count (tens of thousands at
/// a 32x32 image) sets the precomputation's cost, not the light's structure.
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "../util/grid_clusters.hpp"
#include "../util/shepard_weights.hpp"
#include "relight.hpp"

namespace lucent::prt {

/// The chosen vertices and how every vertex is interpolated from them.
struct TransportPoints {
  std::vector<std::uint32_t> vertex;  ///< input vertex index of each point
  util::ShepardWeights toVertices;    ///< every vertex from the points (b = 0: the points are all)
  double cell = 0;                    ///< the grid's cell side (0: every vertex)
  bool spacingLimited = false;        ///< more points than the budget, to keep `cell` within bound

  bool everyVertex() const { return toVertices.b == 0; }
};

/// At most `budget` points (0: every vertex), but never a grid cell wider than `maxCell` (the
/// points' spacing stays within the profile's width).
inline TransportPoints chooseTransportPoints(const std::vector<glm::dvec3>& positions,
                                             const std::vector<glm::dvec3>& normals,
                                             std::size_t budget, double maxCell,
                                             const util::ParallelFor& parallelFor) {
  TransportPoints out;
  if (budget == 0 || positions.size() <= budget || !(maxCell > 0)) {
    out.vertex.resize(positions.size());
    for (std::size_t v = 0; v < positions.size(); ++v) out.vertex[v] = std::uint32_t(v);
    return out;
  }
  // The count falls as the cell grows: bisect for the finest cell within the budget.
  double fine = 0, coarse = maxCell;
  auto count = [&](double cell) { return util::gridClusters(positions, normals, cell).count; };
  if (count(coarse) > budget) {
    out.spacingLimited = true;
  } else {
    for (int i = 0; i < 16; ++i) {  // the cell to 1/65536 of maxCell
      const double mid = 0.5 * (fine + coarse);
      (count(mid) > budget ? fine : coarse) = mid;
    }
  }
  out.cell = coarse;
  // One point per cluster: the vertex nearest its mean position.
  out.vertex = util::gridClusters(positions, normals, out.cell).representatives(positions);
  std::vector<glm::dvec3> pointPositions, pointNormals;
  for (std::uint32_t v : out.vertex)
    pointPositions.push_back(positions[v]), pointNormals.push_back(normals[v]);
  out.toVertices = util::facingShepardWeights(util::NearestPoints(pointPositions), pointNormals,
                                              positions, normals, 4, parallelFor);
  return out;
}

/// The points' relit shading at every vertex.
inline VertexShading shadingOnVertices(const TransportPoints& points, VertexShading atPoints) {
  if (points.everyVertex()) return atPoints;
  const std::size_t vertices = points.toVertices.index.size() / points.toVertices.b;
  VertexShading out;
  out.diffuse.resize(vertices);
  out.single.resize(atPoints.single.empty() ? 0 : vertices);
  for (std::size_t v = 0; v < vertices; ++v) {
    out.diffuse[v] = points.toVertices.at(atPoints.diffuse, v);
    if (atPoints.single.empty()) continue;
    const util::ShepardWeights& w = points.toVertices;
    out.single[v].assign(atPoints.single[w.index[v * w.b]].size(), glm::dvec3(0));
    for (std::size_t k = 0; k < w.b; ++k)
      for (std::size_t t = 0; t < out.single[v].size(); ++t)
        out.single[v][t] += w.weight[v * w.b + k] * atPoints.single[w.index[v * w.b + k]][t];
  }
  return out;
}

}  // namespace lucent::prt
