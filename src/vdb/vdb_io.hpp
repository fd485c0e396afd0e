#pragma once
/// @file vdb_io.hpp
/// @brief OpenVDB float grids to and from lucent's dense VoxelGrid (the active bounding box is
/// densified; inactive voxels take the grid's background value). The voxel size must be uniform.
#include <string>
#include <vector>

#include <lucent/scene/voxel_grid.hpp>

namespace lucent::vdb {

/// Reads the float grid named `gridName` ("" = the first float grid). Throws InputError naming the
/// file, the problem (missing, not a VDB, no such grid, not a float grid, non-uniform voxels) and
/// the fix.
scene::VoxelGrid readFloatGrid(const std::string& path, const std::string& gridName = "");
/// Names of the grids in a file (to tell the user what is there).
std::vector<std::string> gridNames(const std::string& path);
/// Writes the grid as a sparse float grid (values equal to `background` stay inactive).
void writeFloatGrid(const std::string& path, const scene::VoxelGrid& grid,
                    const std::string& gridName, float background = 0.0f);

}  // namespace lucent::vdb
