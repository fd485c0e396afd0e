#pragma once
/// @file vtk_volume.hpp
/// @brief A scanned volume from a VTK image file (.vti, or legacy .vtk structured points) as lucent's
/// dense VoxelGrid: the path by which a ParaView user's CT or MRI scan becomes a medium.
#include <string>

#include <lucent/scene/voxel_grid.hpp>

namespace lucent::io {

/// Reads one point-data array (`arrayName`, "" = the active scalars or else the first array) as floats;
/// a multi-component array gives its magnitude. Throws InputError naming the file, the problem (missing,
/// unreadable, no such array, non-cubic voxels, empty) and the fix.
scene::VoxelGrid readImageVolume(const std::string& path, const std::string& arrayName = "");

}  // namespace lucent::io
