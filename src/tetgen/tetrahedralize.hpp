#pragma once
/// @file tetrahedralize.hpp
/// @brief Quality tetrahedralization of a closed triangle mesh with TetGen.
///
/// Licence: this target links Debian's libtet (TetGen 1.5), which is AGPL-3.0-or-later. It is kept in its
/// own CMake target (lucent_tetgen, option LUCENT_WITH_TETGEN) so that a build without it is BSD-only.
#include <lucent/scene/mesh.hpp>
#include <lucent/scene/tet_mesh.hpp>

namespace lucent::tetgen {

struct TetOptions {
  double radiusEdgeRatio = 2.0;     ///< TetGen -q: quality bound (smaller = rounder tets, more of them)
  double maxVolume = 0;             ///< TetGen -a: target largest tet volume in mm^3 (0 = none); TetGen may exceed it
                                    ///< slightly, and with preserveSurface by more at the surface
  /// TetGen -Y: no Steiner points on the surface (faces stay the input's). K's grading pass splits them
  /// (each piece keeps its source triangle) where keeping them spent its budget (TetReport::surfaceSplit).
  bool preserveSurface = true;
  long maxSteinerPoints = 2000000;  ///< TetGen -S: bounds TetGen's effort, so bad input cannot run forever
  /// The QuadGraph paper's K (Sec. 4.1, after Alliez et al. 2005): target edge length h(x) = h_s + K d(x),
  /// h_s the mean surface edge, d the distance to the surface. Small K: inner tets close to surface size
  /// (many tets); large K: they grow fast. Negative: TetGen's own grading (quality bound only).
  double gradingK = -1;
};

/// What the grading pass did: Steiner points it was allowed and used (used == budget: stopped by the
/// budget, the sizes are not met everywhere; seen on contoured surfaces with tiny triangles).
struct TetReport {
  std::size_t steinerBudget = 0, steinerUsed = 0;
  bool surfaceSplit = false;  ///< the grading split surface faces (preserving them had spent the budget)
  bool budgetLimited() const { return steinerBudget > 0 && steinerUsed >= steinerBudget; }
};

/// Boundary faces carry the input triangle they lie on (TetMesh::boundarySource).
/// Cavities (closed components facing inward, e.g. the cube-cavity shape) are found and left empty.
/// Throws InputError naming the problem (self-intersection, tiny features, close facets) and the repair.
scene::TetMesh tetrahedralize(const scene::TriangleMesh& surface, const TetOptions& options = {},
                              TetReport* report = nullptr);

}  // namespace lucent::tetgen
