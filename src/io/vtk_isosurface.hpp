#pragma once
/// @file vtk_isosurface.hpp
/// @brief The closed surface where an image's scalars cross a value (VTK's flying edges), welded
/// and turned outward: the built-in implicit shapes and a scan's isosurface (`--volume --iso`).
#include <string>

#include <lucent/scene/mesh.hpp>
#include <lucent/scene/voxel_grid.hpp>

class vtkImageData;

namespace lucent::io {

/// Contours `image`'s active scalars at `value`, turned so that its volume is positive (inner
/// shells, cavities, then face inward). The image must not reach the value on its border, or the
/// surface is cut open there.
scene::TriangleMesh isosurfaceOf(vtkImageData* image, double value);

/// The isosurface of a scan at `iso`, closed: the grid is padded by one voxel below the threshold,
/// so a structure touching the scan's border is capped there. Throws InputError naming `what` when
/// no voxel lies above `iso` (or every one does), with the range of the values.
scene::TriangleMesh scanIsosurface(const scene::VoxelGrid& grid, double iso,
                                   const std::string& what);

}  // namespace lucent::io
