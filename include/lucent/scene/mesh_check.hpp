#pragma once
/// @file mesh_check.hpp
/// @brief Checks that a mesh bounds a volume: watertight, manifold, no degenerate faces, consistently and
/// outwardly oriented. Every subsurface technique assumes this; a failing mesh gets a message with a fix.
#include <algorithm>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "mesh.hpp"

namespace lucent::scene {

struct MeshReport {
  std::size_t triangles = 0;
  std::size_t degenerateFaces = 0;     ///< area below 1e-12 of the squared diagonal
  std::size_t boundaryEdges = 0;       ///< edges used by one face: holes
  std::size_t nonManifoldEdges = 0;    ///< edges used by three or more faces
  std::size_t inconsistentEdges = 0;   ///< edges two faces traverse in the same direction
  double signedVolume = 0;             ///< mm^3; negative when faces point inward

  bool watertight() const { return boundaryEdges == 0; }
  bool manifold() const { return nonManifoldEdges == 0; }
  bool consistentlyOriented() const { return inconsistentEdges == 0; }
  bool outward() const { return signedVolume > 0; }
  bool ok() const {
    return triangles > 0 && degenerateFaces == 0 && watertight() && manifold() && consistentlyOriented() && outward();
  }

  /// One line per problem, each naming what to do about it; empty when the mesh is fine.
  std::vector<std::string> problems() const {
    std::vector<std::string> out;
    if (triangles == 0) out.push_back("the mesh has no triangles: check that the file holds polygons, not only points or lines");
    if (degenerateFaces)
      out.push_back(std::to_string(degenerateFaces) + " degenerate (zero-area) faces: remove them, e.g. with vtkCleanPolyData or MeshLab's 'Remove Zero Area Faces'");
    if (boundaryEdges)
      out.push_back(std::to_string(boundaryEdges) + " boundary edges: the mesh has holes and bounds no volume; close them, e.g. with vtkFillHolesFilter");
    if (nonManifoldEdges)
      out.push_back(std::to_string(nonManifoldEdges) + " non-manifold edges (shared by 3+ faces): split or repair them, e.g. MeshLab's 'Repair non Manifold Edges'");
    if (inconsistentEdges)
      out.push_back(std::to_string(inconsistentEdges) + " edges with inconsistent face orientation: reorient, e.g. with vtkPolyDataNormals (ConsistencyOn)");
    if (triangles > 0 && inconsistentEdges == 0 && !(signedVolume > 0))
      out.push_back("faces point inward (signed volume <= 0): flip them, e.g. vtkPolyDataNormals with AutoOrientNormalsOn");
    return out;
  }
};

inline MeshReport checkMesh(const TriangleMesh& mesh) {
  MeshReport r;
  r.triangles = mesh.triangles.size();
  const double diag = mesh.bounds().diagonal();
  const double minArea = 1e-12 * diag * diag;
  // Directed edge (a,b) -> count. An undirected edge is used twice, once in each direction, on a
  // closed, consistently oriented manifold.
  std::unordered_map<std::uint64_t, int> directed;
  directed.reserve(mesh.triangles.size() * 3);
  auto key = [](std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; };
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    if (!(mesh.triangleArea(t) > minArea) || tri.x == tri.y || tri.y == tri.z || tri.x == tri.z) {
      ++r.degenerateFaces;
      continue;
    }
    for (int k = 0; k < 3; ++k) ++directed[key(tri[k], tri[(k + 1) % 3])];
  }
  for (const auto& [k, count] : directed) {
    const auto a = std::uint32_t(k >> 32), b = std::uint32_t(k & 0xffffffffu);
    const auto it = directed.find(key(b, a));
    const int reverse = it == directed.end() ? 0 : it->second;
    if (a > b && reverse > 0) continue;  // the pair is counted once, from its smaller-index side
    const int uses = count + reverse;
    if (uses == 1) ++r.boundaryEdges;
    else if (uses > 2) ++r.nonManifoldEdges;
    else if (count == 2 || reverse == 2) ++r.inconsistentEdges;
  }
  r.signedVolume = mesh.signedVolume();
  return r;
}

}  // namespace lucent::scene
