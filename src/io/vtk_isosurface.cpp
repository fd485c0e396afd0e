#include "vtk_isosurface.hpp"

#include <string>

#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <lucent/scene/shapes.hpp>

#include "../util/error.hpp"
#include "lucentScanSurface.h"
#include "vtk_mesh.hpp"

namespace lucent::io {

namespace {
scene::TriangleMesh outwardMesh(vtkPolyData* surface) {
  scene::TriangleMesh m = fromPolyData(surface);
  scene::shapes::detail::orientOutward(m);
  return m;
}
}  // namespace

scene::TriangleMesh isosurfaceOf(vtkImageData* image, double value) {
  return outwardMesh(vtkadapter::contourWelded(image, value));
}

scene::TriangleMesh scanIsosurface(const scene::VoxelGrid& grid, double iso,
                                   const std::string& what) {
  try {
    return outwardMesh(
        vtkadapter::closedIsosurface(grid, iso, what, "pick --iso inside that range"));
  } catch (const technique::RequestError& e) {
    throw InputError(e.what());
  }
}

}  // namespace lucent::io
