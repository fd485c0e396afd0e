#pragma once
/// @file mesh_repair.hpp
/// @brief `--repair`: what a laser scan or a careless export needs before it bounds a volume, with
/// VTK's filters: weld coincident points and drop degenerate and duplicate faces
/// (vtkCleanPolyData), close holes (vtkFillHolesFilter, any size), orient every face consistently
/// and outward (vtkPolyDataNormals with AutoOrientNormals). The mesh check then runs again; the
/// report says what changed.
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
  /// One line a change, for the user.
  std::vector<std::string> changes() const;
};

/// Repairs `mesh` in place (its units); returns what changed.
RepairReport repairMesh(scene::TriangleMesh& mesh);

}  // namespace lucent::io
