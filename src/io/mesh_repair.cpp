#include "mesh_repair.hpp"

#include <cstdio>
#include <utility>

#include <vtkCleanPolyData.h>
#include <vtkFillHolesFilter.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkTriangleFilter.h>

#include <lucent/scene/mesh_check.hpp>

#include "quiet_vtk.hpp"
#include "vtk_mesh.hpp"
#include "winding_remesh.hpp"

namespace lucent::io {

std::vector<std::string> RepairReport::changes() const {
  std::vector<std::string> out;
  if (pointsAfter != pointsBefore && !remeshed)
    out.push_back("welded " + std::to_string(pointsBefore) + " points into " +
                  std::to_string(pointsAfter));
  if (degenerateBefore)
    out.push_back("removed " + std::to_string(degenerateBefore) + " degenerate faces");
  if (boundaryEdgesBefore != boundaryEdgesAfter)
    out.push_back("closed holes: " + std::to_string(boundaryEdgesBefore) +
                  " boundary edges before, " + std::to_string(boundaryEdgesAfter) + " after");
  if (trianglesAfter != trianglesBefore && !remeshed)
    out.push_back(std::to_string(trianglesBefore) + " triangles became " +
                  std::to_string(trianglesAfter));
  if (turnedOutward) out.push_back("oriented every face outward");
  if (remeshed) {
    char line[480];
    std::snprintf(line, sizeof line,
                  "welding, filling and orienting were not enough: remeshed by generalized "
                  "winding number at %d voxels along the longest side (voxel %.3g), %zu "
                  "triangles became %zu; the result lies within %.3g of the input (%.2g %% of "
                  "the diagonal; mean %.3g), the input within %.3g of the result (%.2g %%; mean "
                  "%.3g), in the mesh's units",
                  resolution, voxel, trianglesBefore, trianglesAfter, resultToInputMax,
                  100 * resultToInputMax / diagonal, resultToInputMean, inputToResultMax,
                  100 * inputToResultMax / diagonal, inputToResultMean);
    out.push_back(line);
  }
  return out;
}

namespace {
/// The cheap steps: weld, drop degenerate faces, fill holes (when `fillHoles`), orient consistently
/// and outward.
scene::TriangleMesh cheapRepair(const scene::TriangleMesh& mesh, bool fillHoles, bool& flipped) {
  const double diagonal = mesh.bounds().diagonal();

  const QuietVtk quiet;
  const vtkSmartPointer<vtkPolyData> input = toPolyData(mesh);
  vtkNew<vtkCleanPolyData>
      weld;  // coincident points, degenerate faces (as lines/points, then dropped)
  weld->SetInputData(input);
  weld->PointMergingOn();
  weld->SetTolerance(0.0);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(weld->GetOutputPort());
  triangles->PassLinesOff();
  triangles->PassVertsOff();
  vtkNew<vtkFillHolesFilter> fill;  // holes of any size: a scan's open bottom too
  fill->SetInputConnection(triangles->GetOutputPort());
  fill->SetHoleSize(fillHoles ? 10 * diagonal : 0.0);
  vtkNew<vtkTriangleFilter> fillTriangles;  // the patches are polygons
  fillTriangles->SetInputConnection(fill->GetOutputPort());
  vtkNew<vtkPolyDataNormals> orient;
  orient->SetInputConnection(fillTriangles->GetOutputPort());
  orient->ConsistencyOn();
  orient->AutoOrientNormalsOn();
  orient->SplittingOff();
  orient
      ->ComputePointNormalsOn();  // with no normals asked for, the filter passes its input through
  orient->Update();

  return fromPolyData(orient->GetOutput(), &flipped);
}
}  // namespace

RepairReport repairMesh(scene::TriangleMesh& mesh, int resolution, const std::string& what) {
  RepairReport r;
  const scene::MeshReport before = scene::checkMesh(mesh);
  r.trianglesBefore = mesh.triangles.size();
  r.pointsBefore = mesh.positions.size();
  r.boundaryEdgesBefore = before.boundaryEdges;
  r.degenerateBefore = before.degenerateFaces;
  r.diagonal = mesh.bounds().diagonal();
  scene::TriangleMesh repaired = cheapRepair(mesh, true, r.turnedOutward);
  if (!scene::checkMesh(repaired).ok()) {
    // The soup welded and, where it can be, consistently wound; its holes left to the field.
    bool flipped = false;
    const scene::TriangleMesh soup = cheapRepair(mesh, false, flipped);
    const RemeshResult remesh =
        remeshByWindingNumber(soup.triangles.empty() ? mesh : soup, mesh, resolution, what);
    repaired = remesh.mesh;
    r.remeshed = true, r.resolution = resolution, r.voxel = remesh.voxel;
    r.resultToInputMax = remesh.resultToInputMax, r.resultToInputMean = remesh.resultToInputMean;
    r.inputToResultMax = remesh.inputToResultMax, r.inputToResultMean = remesh.inputToResultMean;
  }
  mesh = std::move(repaired);
  const scene::MeshReport after = scene::checkMesh(mesh);
  r.trianglesAfter = mesh.triangles.size();
  r.pointsAfter = mesh.positions.size();
  r.boundaryEdgesAfter = after.boundaryEdges;
  r.degenerateAfter = after.degenerateFaces;
  r.turnedOutward = r.turnedOutward || (before.signedVolume <= 0 && after.signedVolume > 0) ||
                    before.inconsistentEdges > 0;
  return r;
}

}  // namespace lucent::io
