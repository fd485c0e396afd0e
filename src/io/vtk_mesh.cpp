#include "vtk_mesh.hpp"

#include <vtkCellArray.h>
#include <vtkCleanPolyData.h>
#include <vtkIdList.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>

namespace lucent::io {

scene::TriangleMesh fromPolyData(vtkPolyData* polyData) {
  auto triangulate = vtkSmartPointer<vtkTriangleFilter>::New();
  triangulate->SetInputData(polyData);
  triangulate->PassLinesOff();
  triangulate->PassVertsOff();
  // Merge points that coincide exactly (STL stores each triangle's corners separately).
  auto clean = vtkSmartPointer<vtkCleanPolyData>::New();
  clean->SetInputConnection(triangulate->GetOutputPort());
  clean->PointMergingOn();
  clean->SetTolerance(0.0);
  clean->ConvertLinesToPointsOff();
  clean->ConvertPolysToLinesOff();
  clean->Update();
  vtkPolyData* out = clean->GetOutput();

  scene::TriangleMesh mesh;
  mesh.positions.resize(std::size_t(out->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
    double p[3];
    out->GetPoint(i, p);
    mesh.positions[std::size_t(i)] = glm::vec3(p[0], p[1], p[2]);
  }
  vtkCellArray* polys = out->GetPolys();
  auto ids = vtkSmartPointer<vtkIdList>::New();
  polys->InitTraversal();
  while (polys->GetNextCell(ids))
    if (ids->GetNumberOfIds() == 3)
      mesh.triangles.push_back({unsigned(ids->GetId(0)), unsigned(ids->GetId(1)), unsigned(ids->GetId(2))});
  return mesh;
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
