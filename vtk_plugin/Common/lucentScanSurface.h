/// @file lucentScanSurface.h
/// @brief A scan (vtkImageData) as lucent reads it, for the CLI's `--volume` and
/// vtkLucentVolumeFilter alike: one array as a VoxelGrid (checked: spacing, extent, finite values)
/// and its closed isosurface at a threshold (padded by one voxel below it, so a structure touching
/// the scan's border is capped; the values kept off the threshold by scene::keepOffThreshold, so
/// the surface is a closed 2-manifold at any threshold; contoured by VTK's flying edges). Errors
/// are lucent::technique::RequestError naming `what`, the problem and the fix.
#ifndef lucentScanSurface_h
#define lucentScanSurface_h

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <vtkCleanPolyData.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <lucent/scene/iso_margin.hpp>
#include <lucent/scene/voxel_grid.hpp>
#include <lucent/technique/knob.hpp>
#include <lucent/technique/validity.hpp>

namespace lucent::vtkadapter {

/// `array` (point data of `image`; several components: their magnitude) times slope plus
/// intercept, at the image's origin and spacing.
inline scene::VoxelGrid voxelGridOf(vtkImageData* image, vtkDataArray* array,
                                    const std::string& what, double slope = 1,
                                    double intercept = 0) {
  using technique::RequestError;
  int dims[3];
  double spacing[3], origin[3];
  image->GetDimensions(dims);
  image->GetSpacing(spacing);
  image->GetOrigin(origin);
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(spacing[k]) || !std::isfinite(origin[k]))
      throw RequestError(what + ": the volume's spacing or origin is not finite; fix the header");
  const std::string problem = scene::spacingProblem(spacing);
  if (!problem.empty()) throw RequestError(what + ": " + problem + " (fix the header)");
  const double voxels = double(dims[0]) * dims[1] * dims[2];
  if (!(voxels > 0) || voxels > scene::kMaxVoxels)
    throw RequestError(what + ": " + std::to_string(dims[0]) + " x " + std::to_string(dims[1]) +
                       " x " + std::to_string(dims[2]) + " voxels; give 1 to " +
                       std::to_string(scene::kMaxVoxels) + " (resample it, e.g. ResampleToImage)");
  const std::string name = array->GetName() ? array->GetName() : "scalars";
  const vtkIdType n = array->GetNumberOfTuples();
  if (double(n) != voxels)
    throw RequestError(what + ": the array '" + name + "' has " + std::to_string(n) +
                       " values for " + std::to_string(dims[0]) + " x " + std::to_string(dims[1]) +
                       " x " + std::to_string(dims[2]) +
                       " voxels; the extent and data disagree (re-save it)");
  scene::VoxelGrid grid;
  grid.dims = {dims[0], dims[1], dims[2]};
  grid.origin = {origin[0], origin[1], origin[2]};
  grid.spacing = {spacing[0], spacing[1], spacing[2]};
  grid.values.resize(std::size_t(n));
  const int components = array->GetNumberOfComponents();
  for (vtkIdType i = 0; i < n; ++i) {
    double sum = 0;
    for (int c = 0; c < components; ++c)
      sum += array->GetComponent(i, c) * array->GetComponent(i, c);
    const double v =
        slope * (components == 1 ? array->GetComponent(i, 0) : std::sqrt(sum)) + intercept;
    const float stored = float(v);  // finite as a double is not enough: lucent keeps floats
    if (!std::isfinite(stored))
      throw RequestError(what + ": voxel " + std::to_string(i) + " of '" + name + "' is " +
                         technique::numberText(v) +
                         ", not a finite float; replace NaN/inf and values beyond 3.4e38 (e.g. "
                         "ParaView's Calculator) before using it as a medium");
    grid.values[std::size_t(i)] = stored;  // VTK point ids run x fastest, as VoxelGrid's
  }
  return grid;
}

/// Contours `image`'s active scalars at `value` by VTK's flying edges (one point per crossed grid
/// edge, shared by the triangles that use it).
inline vtkSmartPointer<vtkPolyData> contour(vtkImageData* image, double value) {
  auto fe = vtkSmartPointer<vtkFlyingEdges3D>::New();
  fe->SetInputData(image);
  fe->SetValue(0, value);
  fe->ComputeNormalsOff();
  fe->ComputeGradientsOff();
  fe->ComputeScalarsOff();
  fe->Update();
  return fe->GetOutput();
}

/// Contours `image`'s active scalars at `value`, welded: contouring leaves slivers where the
/// surface passes within rounding of a grid node; merging points closer than 1e-5 of the box
/// collapses them into edges, which the cleaner then drops (no holes open).
inline vtkSmartPointer<vtkPolyData> contourWelded(vtkImageData* image, double value) {
  auto weld = vtkSmartPointer<vtkCleanPolyData>::New();
  weld->SetInputData(contour(image, value));
  weld->SetTolerance(1e-5);
  weld->ConvertPolysToLinesOff();
  weld->ConvertLinesToPointsOff();
  weld->Update();
  return weld->GetOutput();
}

/// The closed isosurface of `grid` at `iso` (the grid's coordinates): a 2-manifold with no
/// degenerate face at any threshold, within kIsoVertexMargin of a voxel of the exact one. `fix`
/// says how to pick another threshold ("pick --iso inside that range").
inline vtkSmartPointer<vtkPolyData> closedIsosurface(const scene::VoxelGrid& grid, double iso,
                                                     const std::string& what,
                                                     const std::string& fix) {
  const auto [lo, hi] = std::minmax_element(grid.values.begin(), grid.values.end());
  if (grid.values.empty() || !(*hi > iso) || !(*lo <= iso))
    throw technique::RequestError(
        what + ": the threshold " + technique::valueText(iso) + " selects " +
        (grid.values.empty() || !(*hi > iso) ? "no voxel" : "every voxel") + " (the values span [" +
        (grid.values.empty() ? std::string("none") : technique::valueText(*lo)) + ", " +
        (grid.values.empty() ? std::string("none") : technique::valueText(*hi)) + "]); " + fix);
  const int dims[3] = {grid.dims.x + 2, grid.dims.y + 2, grid.dims.z + 2};
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(dims);
  const glm::dvec3 origin = grid.origin - grid.spacing;
  image->SetOrigin(origin.x, origin.y, origin.z);
  image->SetSpacing(grid.spacing.x, grid.spacing.y, grid.spacing.z);
  // Offsets from the threshold (contoured at 0), so that the margin is exact near it in float.
  std::vector<float> offsets(std::size_t(dims[0]) * dims[1] * dims[2]);
  const float below = float(std::min(double(*lo), iso) - 1.0 - iso);
  std::size_t id = 0;
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i) {
        const bool inside =
            i > 0 && j > 0 && k > 0 && i <= grid.dims.x && j <= grid.dims.y && k <= grid.dims.z;
        offsets[id++] = inside ? float(double(grid.at(i - 1, j - 1, k - 1)) - iso) : below;
      }
  scene::keepOffThreshold(offsets, glm::ivec3(dims[0], dims[1], dims[2]));
  auto values = vtkSmartPointer<vtkFloatArray>::New();
  values->SetNumberOfTuples(vtkIdType(offsets.size()));
  std::copy(offsets.begin(), offsets.end(), values->GetPointer(0));
  offsets = {};
  image->GetPointData()->SetScalars(values);
  auto surface = contour(image, 0.0);
  if (surface->GetNumberOfPolys() == 0)
    throw technique::RequestError(what + ": the isosurface at " + std::to_string(iso) +
                                  " has no triangles; " + fix);
  return surface;
}

}  // namespace lucent::vtkadapter

#endif
