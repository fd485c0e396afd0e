#pragma once
/// @file node_surface.hpp
/// @brief The display surface of Wang et al. 2010 Sec. 5.3: a triangulation whose vertices are exactly
/// the QuadGraph's surface nodes, so Eq. 7's radiance is shown where it was computed and follows a
/// deformation of the graph without any mapping back to the input mesh.
///
/// Construction: the dual of the tet mesh's boundary. Every boundary vertex is surrounded by a cycle of
/// boundary faces, each holding one surface node; that cycle of nodes is a polygon, cut into triangles by
/// repeatedly clipping the ear with the shortest diagonal. A closed boundary with F faces and genus g gives
/// 2F - 4 + 4g triangles over F vertices: the same genus as the input. Faces are ordered counter-clockwise
/// seen from outside, so the triangles face outward as the boundary does.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

#include <glm/geometric.hpp>

#include "../scene/mesh.hpp"
#include "quad_graph.hpp"

namespace lucent::quadgraph {

/// Triangles over surface-node indices s in [0, surfaceCount()); positions come from the graph.
struct NodeSurface {
  std::vector<glm::uvec3> triangles;
  std::size_t openFans = 0;  ///< boundary vertices whose face cycle did not close (not a closed 2-manifold)

  /// The surface as a mesh at the graph's current node positions (call again after a deformation).
  scene::TriangleMesh mesh(const QuadGraph& g) const {
    scene::TriangleMesh m;
    m.positions.reserve(g.surfaceCount());
    for (std::size_t s = 0; s < g.surfaceCount(); ++s) m.positions.push_back(glm::vec3(g.positions[g.innerCount() + s]));
    m.triangles = triangles;
    return m;
  }
};

namespace detail {

/// Cuts a polygon (node indices in order) into triangles, clipping the ear with the shortest diagonal first:
/// on the near-planar, near-convex fans of a boundary vertex this keeps triangles close to equilateral.
inline void triangulatePolygon(std::vector<std::uint32_t> ring, const QuadGraph& g, std::vector<glm::uvec3>& out) {
  const auto at = [&](std::uint32_t s) { return g.positions[g.innerCount() + s]; };
  while (ring.size() > 3) {
    std::size_t best = 0;
    double bestLength = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const std::uint32_t prev = ring[(k + ring.size() - 1) % ring.size()], next = ring[(k + 1) % ring.size()];
      const double length = glm::length(at(next) - at(prev));
      if (length < bestLength) bestLength = length, best = k;
    }
    const std::size_t prev = (best + ring.size() - 1) % ring.size(), next = (best + 1) % ring.size();
    out.push_back({ring[prev], ring[best], ring[next]});
    ring.erase(ring.begin() + std::ptrdiff_t(best));
  }
  if (ring.size() == 3) out.push_back({ring[0], ring[1], ring[2]});
}

}  // namespace detail

/// Builds the Sec. 5.3 triangulation from the graph's boundary faces (topology only: valid after deform()).
inline NodeSurface triangulateSurfaceNodes(const QuadGraph& g) {
  // For every boundary vertex v, each incident face (v, a, b) in outward (counter-clockwise) order links
  // a -> b, and the face after it is (v, b, c): walking the links visits the faces counter-clockwise around
  // v seen from outside, so the polygon of their nodes is counter-clockwise too.
  struct Corner {
    std::uint32_t vertex, from, to, node;
  };
  std::vector<Corner> corners;
  corners.reserve(3 * g.surfaceCount());
  for (std::size_t s = 0; s < g.surfaceCount(); ++s) {
    const glm::uvec3 f = tetFace(g.cells[g.surfaceInner[s]], g.surfaceSlot[s]);
    for (int k = 0; k < 3; ++k) corners.push_back({f[k], f[(k + 1) % 3], f[(k + 2) % 3], std::uint32_t(s)});
  }
  std::sort(corners.begin(), corners.end(), [](const Corner& a, const Corner& b) { return a.vertex < b.vertex; });

  NodeSurface out;
  out.triangles.reserve(2 * g.surfaceCount());
  std::unordered_map<std::uint32_t, std::size_t> byFrom;
  std::vector<bool> used;
  for (std::size_t begin = 0; begin < corners.size();) {
    std::size_t end = begin + 1;
    while (end < corners.size() && corners[end].vertex == corners[begin].vertex) ++end;
    // The faces around this vertex; a pinched (non-manifold) vertex yields several cycles, each its own fan.
    byFrom.clear();
    for (std::size_t c = begin; c < end; ++c) byFrom[corners[c].from] = c;
    used.assign(end - begin, false);
    for (std::size_t start = begin; start < end; ++start) {
      if (used[start - begin]) continue;
      std::vector<std::uint32_t> ring;
      std::size_t c = start;
      bool closed = false;
      while (!used[c - begin]) {
        used[c - begin] = true;
        ring.push_back(corners[c].node);
        const auto next = byFrom.find(corners[c].to);
        if (next == byFrom.end()) break;
        c = next->second;
        if (c == start) closed = true;
      }
      if (!closed) ++out.openFans;
      detail::triangulatePolygon(std::move(ring), g, out.triangles);
    }
    begin = end;
  }
  return out;
}

}  // namespace lucent::quadgraph
