#include "vtk_quadgraph.hpp"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkQuadricDecimation.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "../util/error.hpp"
#include "atomic_file.hpp"
#include "vtk_mesh.hpp"

namespace lucent::io {

void writeQuadGraphVtu(const std::string& path, const quadgraph::QuadGraph& g,
                       const std::map<std::string, std::vector<double>>& nodeFields) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(vtkIdType(g.nodeCount()));
  for (std::size_t n = 0; n < g.nodeCount(); ++n)
    points->SetPoint(vtkIdType(n), g.positions[n].x, g.positions[n].y, g.positions[n].z);
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->Allocate(vtkIdType(2 * g.innerCount()));
  for (std::size_t i = 0; i < g.innerCount(); ++i)
    for (std::uint32_t j : g.neighbours[i])
      if (j > i) {  // each edge once (inner-inner edges appear in both rows; surface edges only here)
        const vtkIdType ids[2] = {vtkIdType(i), vtkIdType(j)};
        grid->InsertNextCell(VTK_LINE, 2, ids);
      }
  auto kind = vtkSmartPointer<vtkUnsignedCharArray>::New();
  kind->SetName("surface");
  kind->SetNumberOfValues(vtkIdType(g.nodeCount()));
  for (std::size_t n = 0; n < g.nodeCount(); ++n) kind->SetValue(vtkIdType(n), g.isSurface(n) ? 1 : 0);
  grid->GetPointData()->AddArray(kind);
  for (const auto& [name, values] : nodeFields) {
    if (values.size() != g.nodeCount())
      throw InputError("cannot write '" + path + "': field '" + name + "' has " + std::to_string(values.size()) +
                       " values for " + std::to_string(g.nodeCount()) + " nodes (internal error)");
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(name.c_str());
    array->SetNumberOfValues(vtkIdType(values.size()));
    for (std::size_t n = 0; n < values.size(); ++n) array->SetValue(vtkIdType(n), values[n]);
    grid->GetPointData()->AddArray(array);
  }
  AtomicFile out(path);
  auto writer = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
  writer->SetFileName(out.tempPath().c_str());
  writer->SetInputData(grid);
  writer->SetDataModeToAppended();
  writer->SetCompressorTypeToZLib();
  if (writer->Write() != 1) throw InputError("cannot write '" + path + "': VTK's writer failed; check free space and permissions");
  out.commit();
}

scene::TriangleMesh decimate(const scene::TriangleMesh& mesh, std::size_t targetTriangles) {
  if (targetTriangles >= mesh.triangles.size()) return mesh;
  auto filter = vtkSmartPointer<vtkQuadricDecimation>::New();
  filter->SetInputData(toPolyData(mesh));
  filter->SetTargetReduction(1.0 - double(targetTriangles) / double(mesh.triangles.size()));
  filter->VolumePreservationOn();
  filter->Update();
  return fromPolyData(filter->GetOutput());
}

}  // namespace lucent::io
