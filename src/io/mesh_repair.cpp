#include "mesh_repair.hpp"

#include <vtkCleanPolyData.h>
#include <vtkFillHolesFilter.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkTriangleFilter.h>

#include <lucent/scene/mesh_check.hpp>

#include "quiet_vtk.hpp"
#include "vtk_mesh.hpp"

namespace lucent::io {

std::vector<std::string> RepairReport::changes() const {
  std::vector<std::string> out;
  if (pointsAfter != pointsBefore)
    out.push_back("welded " + std::to_string(pointsBefore) + " points into " +
                  std::to_string(pointsAfter));
  if (degenerateBefore)
    out.push_back("removed " + std::to_string(degenerateBefore) + " degenerate faces");
  if (boundaryEdgesBefore != boundaryEdgesAfter)
    out.push_back("closed holes: " + std::to_string(boundaryEdgesBefore) +
                  " boundary edges before, " + std::to_string(boundaryEdgesAfter) + " after");
  if (trianglesAfter != trianglesBefore)
    out.push_back(std::to_string(trianglesBefore) + " triangles became " +
                  std::to_string(trianglesAfter));
  if (turnedOutward) out.push_back("oriented every face outward");
  return out;
}

RepairReport repairMesh(scene::TriangleMesh& mesh) {
  RepairReport r;
  const scene::MeshReport before = scene::checkMesh(mesh);
  r.trianglesBefore = mesh.triangles.size();
  r.pointsBefore = mesh.positions.size();
  r.boundaryEdgesBefore = before.boundaryEdges;
  r.degenerateBefore = before.degenerateFaces;
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
  fill->SetHoleSize(10 * diagonal);
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

  mesh = fromPolyData(orient->GetOutput(), &r.turnedOutward);
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
