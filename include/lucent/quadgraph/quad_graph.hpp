#pragma once
/// @file quad_graph.hpp
/// @brief The QuadGraph (Wang et al. 2010 Sec. 4.1): the connectivity graph of a tetrahedralization.
/// Tets with two or more boundary faces are split at their centroid (Fig. 4) so that every tet has at most
/// one; each tet becomes an inner node (4 neighbours), and each boundary face a surface node linked to its
/// tet's inner node (Fig. 5).
///
/// Topology and geometry are kept apart so that a deformation of the tet vertices (Sec. 6.4) only needs
/// updateGeometry(): node positions are stored as barycentric coordinates in their tet or face.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "../scene/tet_mesh.hpp"

namespace lucent::quadgraph {

inline constexpr std::uint32_t kNoSource = std::numeric_limits<std::uint32_t>::max();

/// Local face k of a tet is the one opposite vertex k.
inline glm::uvec3 tetFace(const glm::uvec4& t, int k) {
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  return {t[kFaces[k][0]], t[kFaces[k][1]], t[kFaces[k][2]]};
}

struct QuadGraph {
  // --- topology ---
  std::vector<glm::dvec3> vertices;        ///< tet vertices (mm): the input's, then the split centroids
  std::size_t inputVertexCount = 0;
  std::vector<glm::uvec4> splitParents;    ///< for vertex inputVertexCount + i: the tet it is the centroid of
  std::vector<glm::uvec4> cells;           ///< inner node i's tet, positively oriented
  /// Node indices: inner nodes [0, innerCount()), surface nodes innerCount() + s. neighbours[i][k] is the
  /// node across face k of cell i (an inner node, or the surface node of that boundary face).
  std::vector<std::array<std::uint32_t, 4>> neighbours;
  std::vector<std::uint32_t> surfaceInner;  ///< surface node s's inner node
  std::vector<std::uint8_t> surfaceSlot;    ///< which face of its inner node's cell it sits on
  std::vector<std::uint32_t> surfaceSource; ///< the input surface triangle it lies on (kNoSource if unknown)
  std::vector<glm::dvec4> innerBary;        ///< inner node position in its cell (centroid = 1/4 each)
  std::vector<glm::dvec3> surfaceBary;      ///< surface node position in its face

  // --- geometry (updateGeometry) ---
  std::vector<glm::dvec3> positions;        ///< every node, inner then surface (mm)
  std::vector<double> cellVolume;           ///< per inner node (mm^3)
  std::vector<double> faceArea;             ///< per inner node and slot, 4 each (mm^2)
  std::vector<double> faceDistance;         ///< per slot: n_f . (x_j - x_i) > 0, the two-point flux distance (mm)
  std::vector<double> nodeDistance;         ///< per slot: |x_j - x_i| (mm), the paper's d_ij

  std::size_t innerCount() const { return cells.size(); }
  std::size_t surfaceCount() const { return surfaceInner.size(); }
  std::size_t nodeCount() const { return cells.size() + surfaceInner.size(); }
  bool isSurface(std::size_t node) const { return node >= cells.size(); }

  /// Outward unit normal and area of face k of cell i, from the current vertex positions.
  void faceGeometry(std::size_t i, int k, glm::dvec3& normal, double& area) const {
    const glm::uvec3 f = tetFace(cells[i], k);
    const glm::dvec3 n = glm::cross(vertices[f.y] - vertices[f.x], vertices[f.z] - vertices[f.x]);
    const double len = glm::length(n);
    area = 0.5 * len;
    normal = len > 0 ? n / len : glm::dvec3(0);
  }

  glm::dvec3 innerPosition(std::size_t i) const {
    const glm::uvec4 c = cells[i];
    const glm::dvec4 b = innerBary[i];
    return b.x * vertices[c.x] + b.y * vertices[c.y] + b.z * vertices[c.z] + b.w * vertices[c.w];
  }
  glm::dvec3 surfacePosition(std::size_t s) const {
    const glm::uvec3 f = tetFace(cells[surfaceInner[s]], surfaceSlot[s]);
    const glm::dvec3 b = surfaceBary[s];
    return b.x * vertices[f.x] + b.y * vertices[f.y] + b.z * vertices[f.z];
  }

  /// Moves the input vertices (a deformation that keeps every tet positively oriented) and recomputes all
  /// geometric quantities; the topology and the node barycentrics stay.
  void deform(const std::vector<glm::dvec3>& inputVertices) {
    if (inputVertices.size() != inputVertexCount)
      throw std::invalid_argument("QuadGraph::deform: expected " + std::to_string(inputVertexCount) + " vertices, got " +
                                  std::to_string(inputVertices.size()));
    std::copy(inputVertices.begin(), inputVertices.end(), vertices.begin());
    updateGeometry();
  }

  void updateGeometry() {
    for (std::size_t v = 0; v < splitParents.size(); ++v) {
      const glm::uvec4 p = splitParents[v];
      vertices[inputVertexCount + v] = 0.25 * (vertices[p.x] + vertices[p.y] + vertices[p.z] + vertices[p.w]);
    }
    const std::size_t ni = innerCount();
    positions.resize(nodeCount());
    cellVolume.resize(ni);
    faceArea.assign(4 * ni, 0);
    faceDistance.assign(4 * ni, 0);
    nodeDistance.assign(4 * ni, 0);
    for (std::size_t i = 0; i < ni; ++i) {
      positions[i] = innerPosition(i);
      const glm::uvec4 c = cells[i];
      cellVolume[i] = glm::dot(vertices[c.y] - vertices[c.x],
                               glm::cross(vertices[c.z] - vertices[c.x], vertices[c.w] - vertices[c.x])) / 6.0;
      // A flat sliver's rounding (-1e-19) is no volume: it absorbs nothing, its faces still carry
      // flux. A tet turned inside out (a deformation) or NaN stays as it is, for assemble to refuse.
      if (cellVolume[i] < 0 && cellVolume[i] >= -scene::TetMesh::flatTolerance(vertices, c))
        cellVolume[i] = 0;
    }
    for (std::size_t s = 0; s < surfaceCount(); ++s) positions[ni + s] = surfacePosition(s);
    for (std::size_t i = 0; i < ni; ++i)
      for (int k = 0; k < 4; ++k) {
        glm::dvec3 n;
        double area;
        faceGeometry(i, k, n, area);
        const glm::dvec3 d = positions[neighbours[i][std::size_t(k)]] - positions[i];
        faceArea[4 * i + std::size_t(k)] = area;
        nodeDistance[4 * i + std::size_t(k)] = glm::length(d);
        faceDistance[4 * i + std::size_t(k)] = glm::dot(n, d);
      }
  }

  /// The smallest two-point distance, relative to the local node spacing: > 0 means every flux is well
  /// defined (each node strictly on its side of every face it shares).
  double minFaceDistanceRatio() const {
    double worst = std::numeric_limits<double>::infinity();
    for (std::size_t e = 0; e < faceDistance.size(); ++e)
      if (nodeDistance[e] > 0) worst = std::min(worst, faceDistance[e] / nodeDistance[e]);
    return worst;
  }
};

namespace detail {

struct FaceRecord {
  std::array<std::uint32_t, 3> key;  ///< sorted vertex indices
  std::uint32_t tet;
  std::uint8_t slot;
  bool operator<(const FaceRecord& o) const { return key < o.key; }
};

inline std::array<std::uint32_t, 3> sortedKey(const glm::uvec3& f) {
  std::array<std::uint32_t, 3> k{f.x, f.y, f.z};
  std::sort(k.begin(), k.end());
  return k;
}

/// For every tet and face: the tet across it, or kNoSource for a boundary face.
inline std::vector<std::array<std::uint32_t, 4>> faceAdjacency(const std::vector<glm::uvec4>& tets) {
  std::vector<FaceRecord> faces;
  faces.reserve(4 * tets.size());
  for (std::uint32_t t = 0; t < tets.size(); ++t)
    for (std::uint8_t k = 0; k < 4; ++k) faces.push_back({sortedKey(tetFace(tets[t], k)), t, k});
  std::sort(faces.begin(), faces.end());
  std::vector<std::array<std::uint32_t, 4>> across(tets.size(), {kNoSource, kNoSource, kNoSource, kNoSource});
  for (std::size_t a = 0; a < faces.size();) {
    std::size_t b = a + 1;
    while (b < faces.size() && faces[b].key == faces[a].key) ++b;
    if (b - a > 2)
      throw std::invalid_argument("QuadGraph: a face is shared by " + std::to_string(b - a) +
                                  " tets; the tetrahedralization is not a manifold volume mesh");
    if (b - a == 2) {
      across[faces[a].tet][faces[a].slot] = faces[a + 1].tet;
      across[faces[a + 1].tet][faces[a + 1].slot] = faces[a].tet;
    }
    a = b;
  }
  return across;
}

}  // namespace detail

inline void projectSurfaceNodes(QuadGraph& g);

/// Builds the graph with every node at its cell's centroid (relax() moves them).
/// Throws std::invalid_argument for an empty or non-manifold tet mesh, or an inside-out tet (a flat sliver
/// is kept: a node of no volume between its neighbours).
inline QuadGraph buildQuadGraph(const scene::TetMesh& mesh) {
  if (mesh.tets.empty()) throw std::invalid_argument("QuadGraph: the tet mesh is empty");
  QuadGraph g;
  g.vertices = mesh.positions;
  g.inputVertexCount = mesh.positions.size();
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    if (mesh.inverted(t))
      throw std::invalid_argument("QuadGraph: tet " + std::to_string(t) + " is inside out (negative volume)");

  // Fig. 4: a tet with 2-4 boundary faces becomes four tets around its centroid, each holding one face.
  const auto across = detail::faceAdjacency(mesh.tets);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const int boundary = int(std::count(across[t].begin(), across[t].end(), kNoSource));
    if (boundary < 2) {
      g.cells.push_back(mesh.tets[t]);
      continue;
    }
    const std::uint32_t centre = std::uint32_t(g.vertices.size());
    g.splitParents.push_back(mesh.tets[t]);
    const glm::uvec4 p = mesh.tets[t];
    g.vertices.push_back(0.25 * (g.vertices[p.x] + g.vertices[p.y] + g.vertices[p.z] + g.vertices[p.w]));
    // Face k with the centroid in place of vertex k keeps the parent's orientation.
    for (int k = 0; k < 4; ++k) {
      glm::uvec4 sub = p;
      sub[k] = centre;
      g.cells.push_back(sub);
    }
  }

  // Boundary faces -> the input triangle they lie on.
  std::vector<detail::FaceRecord> sources;
  for (std::size_t f = 0; f < mesh.boundaryFaces.size(); ++f)
    sources.push_back({detail::sortedKey(mesh.boundaryFaces[f]), mesh.boundarySource[f], 0});
  std::sort(sources.begin(), sources.end());

  const auto cellAcross = detail::faceAdjacency(g.cells);
  const std::uint32_t ni = std::uint32_t(g.cells.size());
  g.neighbours.resize(ni);
  g.innerBary.assign(ni, glm::dvec4(0.25));
  for (std::uint32_t i = 0; i < ni; ++i)
    for (std::uint8_t k = 0; k < 4; ++k) {
      if (cellAcross[i][k] != kNoSource) {
        g.neighbours[i][k] = cellAcross[i][k];
        continue;
      }
      if (std::count(cellAcross[i].begin(), cellAcross[i].end(), kNoSource) > 1)
        throw std::logic_error("QuadGraph: a cell kept two boundary faces after the split");
      g.neighbours[i][k] = ni + std::uint32_t(g.surfaceInner.size());
      g.surfaceInner.push_back(i);
      g.surfaceSlot.push_back(k);
      const detail::FaceRecord probe{detail::sortedKey(tetFace(g.cells[i], k)), 0, 0};
      const auto it = std::lower_bound(sources.begin(), sources.end(), probe);
      g.surfaceSource.push_back(it != sources.end() && it->key == probe.key ? it->tet : kNoSource);
      g.surfaceBary.push_back(glm::dvec3(1.0 / 3.0));
    }
  projectSurfaceNodes(g);
  return g;
}

/// Places each surface node where the line from its inner node along the face normal meets the face
/// (Sec. 4.1's ray to the surface), clamped into the face; then the two-point flux through it is exact.
inline void projectSurfaceNodes(QuadGraph& g) {
  for (std::size_t s = 0; s < g.surfaceCount(); ++s) {
    const std::size_t i = g.surfaceInner[s];
    const glm::uvec3 f = tetFace(g.cells[i], g.surfaceSlot[s]);
    const glm::dvec3 a = g.vertices[f.x], b = g.vertices[f.y], c = g.vertices[f.z];
    const glm::dvec3 p = g.innerPosition(i);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double nn = glm::dot(n, n);
    const glm::dvec3 onPlane = p - n * (glm::dot(p - a, n) / nn);
    // Barycentrics of the projected point; clamping keeps the node on the face.
    glm::dvec3 w(glm::dot(glm::cross(c - b, onPlane - b), n), glm::dot(glm::cross(a - c, onPlane - c), n),
                 glm::dot(glm::cross(b - a, onPlane - a), n));
    w = glm::max(w / nn, glm::dvec3(0));
    const double sum = w.x + w.y + w.z;
    g.surfaceBary[s] = sum > 0 ? w / sum : glm::dvec3(1.0 / 3.0);
  }
  g.updateGeometry();
}

/// Bounded relaxation toward even spacing (Sec. 4.1, in place of reaction-diffusion [Tur91]): each inner
/// node moves a fraction `step` toward the mean of its neighbours, but its barycentrics stay >= `margin`,
/// so it never leaves its cell and every two-point distance stays positive.
inline void relax(QuadGraph& g, int iterations, double step = 0.5, double margin = 0.05) {
  for (int it = 0; it < iterations; ++it) {
    std::vector<glm::dvec4> next(g.innerCount());
    for (std::size_t i = 0; i < g.innerCount(); ++i) {
      glm::dvec3 mean(0);
      for (std::uint32_t j : g.neighbours[i]) mean += g.positions[j];
      const glm::dvec3 target = g.positions[i] + step * (0.25 * mean - g.positions[i]);
      // Barycentrics of target in the cell: solve [b-a c-a d-a] (y z w) = target - a.
      const glm::uvec4 c = g.cells[i];
      const glm::dvec3 a = g.vertices[c.x], e1 = g.vertices[c.y] - a, e2 = g.vertices[c.z] - a, e3 = g.vertices[c.w] - a;
      const double det = glm::dot(e1, glm::cross(e2, e3));
      const glm::dvec3 r = target - a;
      glm::dvec4 w(0, glm::dot(r, glm::cross(e2, e3)) / det, glm::dot(e1, glm::cross(r, e3)) / det,
                   glm::dot(e1, glm::cross(e2, r)) / det);
      w.x = 1 - w.y - w.z - w.w;
      w = glm::max(w, glm::dvec4(margin));
      next[i] = w / (w.x + w.y + w.z + w.w);
    }
    g.innerBary = std::move(next);
    g.updateGeometry();
  }
  projectSurfaceNodes(g);
}

}  // namespace lucent::quadgraph
