#include "vtk_mesh.hpp"

#include <utility>

#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include "lucentPolyDataMesh.h"

namespace lucent::io {

scene::TriangleMesh fromPolyData(vtkPolyData* polyData, bool* flipped, std::size_t* missing) {
  vtkadapter::PolyDataMesh converted =
      vtkadapter::meshFromData(polyData);  // as the VTK modules convert
  if (flipped) *flipped = converted.flipped;
  if (missing) *missing = converted.missingTriangles;
  return std::move(converted.mesh);
}

vtkSmartPointer<vtkPolyData> toPolyData(const scene::TriangleMesh& mesh) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(vtkIdType(mesh.positions.size()));
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    points->SetPoint(vtkIdType(i), mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z);
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& t : mesh.triangles) {
    const vtkIdType ids[3] = {vtkIdType(t.x), vtkIdType(t.y), vtkIdType(t.z)};
    polys->InsertNextCell(3, ids);
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetPolys(polys);
  return pd;
}

}  // namespace lucent::io
