#pragma once
/// @file mesh_repair.hpp
/// @brief `--repair`: what a laser scan or a careless export needs before it bounds a volume, with
/// VTK's filters: weld coincident points and drop degenerate and duplicate faces
/// (vtkCleanPolyData), close holes (vtkFillHolesFilter, any size), orient every face consistently
/// and outward (vtkPolyDataNormals with AutoOrientNormals). When the mesh check still fails (holes
/// the filler cannot close, non-manifold edges, self-intersections), the fallback that always
/// succeeds for a soup that encloses something: the generalized winding number remesh
/// (winding_remesh.hpp). The report says what changed and how far the result lies from the input.
#include <string>
#include <vector>

#include <lucent/scene/mesh.hpp>

namespace lucent::io {

struct RepairReport {
  std::size_t trianglesBefore = 0, trianglesAfter = 0;
  std::size_t pointsBefore = 0, pointsAfter = 0;
  std::size_t boundaryEdgesBefore = 0, boundaryEdgesAfter = 0;
  std::size_t degenerateBefore = 0, degenerateAfter = 0;
  bool turnedOutward = false;
  /// The winding-number remesh ran (the cheap steps were not enough): its grid and distances.
  bool remeshed = false;
  int resolution = 0;
  double voxel = 0, diagonal = 0;  ///< the grid's spacing; the input's bounding-box diagonal
  double resultToInputMax = 0, resultToInputMean = 0, inputToResultMax = 0, inputToResultMean = 0;
  /// One line a change, for the user.
  std::vector<std::string> changes() const;
};

/// Repairs `mesh` in place (its units); returns what changed. `resolution`: the remesh's voxels
/// along the longest side, if it runs. Throws InputError naming `what` when the mesh encloses
/// nothing.
RepairReport repairMesh(scene::TriangleMesh& mesh, int resolution, const std::string& what);

}  // namespace lucent::io
