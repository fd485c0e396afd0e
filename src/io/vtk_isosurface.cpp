#include "vtk_isosurface.hpp"

#include <algorithm>
#include <string>

#include <vtkCleanPolyData.h>
#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <lucent/scene/shapes.hpp>

#include "../util/error.hpp"
#include "vtk_mesh.hpp"

namespace lucent::io {

scene::TriangleMesh isosurfaceOf(vtkImageData* image, double value) {
  auto fe = vtkSmartPointer<vtkFlyingEdges3D>::New();
  fe->SetInputData(image);
  fe->SetValue(0, value);
  fe->ComputeNormalsOff();
  fe->ComputeGradientsOff();
  fe->ComputeScalarsOff();
  // Contouring leaves slivers where the surface passes within rounding of a grid node; merging
  // points closer than 1e-5 of the box collapses them into edges, which the cleaner then drops (no
  // holes open).
  auto weld = vtkSmartPointer<vtkCleanPolyData>::New();
  weld->SetInputConnection(fe->GetOutputPort());
  weld->SetTolerance(1e-5);
  weld->ConvertPolysToLinesOff();
  weld->ConvertLinesToPointsOff();
  weld->Update();
  scene::TriangleMesh m = fromPolyData(weld->GetOutput());
  scene::shapes::detail::orientOutward(m);
  return m;
}

scene::TriangleMesh scanIsosurface(const scene::VoxelGrid& grid, double iso,
                                   const std::string& what) {
  const auto [lo, hi] = std::minmax_element(grid.values.begin(), grid.values.end());
  if (grid.values.empty() || !(*hi > iso) || !(*lo <= iso))
    throw InputError(what + ": the threshold " + std::to_string(iso) + " selects " +
                     (grid.values.empty() || !(*hi > iso) ? "no voxel" : "every voxel") +
                     " (the values span [" +
                     (grid.values.empty() ? std::string("none") : std::to_string(*lo)) + ", " +
                     (grid.values.empty() ? std::string("none") : std::to_string(*hi)) +
                     "]); pick --iso inside that range");
  // Padded by one voxel below the threshold on every side, so the surface closes.
  const glm::ivec3 dims = grid.dims + 2;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(dims.x, dims.y, dims.z);
  const glm::dvec3 origin = grid.origin - grid.spacing;
  image->SetOrigin(origin.x, origin.y, origin.z);
  image->SetSpacing(grid.spacing.x, grid.spacing.y, grid.spacing.z);
  auto values = vtkSmartPointer<vtkFloatArray>::New();
  values->SetNumberOfTuples(vtkIdType(dims.x) * dims.y * dims.z);
  const float below = float(std::min(double(*lo), iso) - 1.0);
  vtkIdType id = 0;
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i) {
        const bool inside =
            i > 0 && j > 0 && k > 0 && i <= grid.dims.x && j <= grid.dims.y && k <= grid.dims.z;
        values->SetValue(id++, inside ? grid.at(i - 1, j - 1, k - 1) : below);
      }
  image->GetPointData()->SetScalars(values);
  scene::TriangleMesh m = isosurfaceOf(image, iso);
  if (m.triangles.empty())
    throw InputError(what + ": the isosurface at " + std::to_string(iso) +
                     " has no triangles; pick another --iso");
  return m;
}

}  // namespace lucent::io
