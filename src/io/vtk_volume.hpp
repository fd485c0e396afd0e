#pragma once
/// @file vtk_volume.hpp
/// @brief A scanned volume read by VTK (.vti, legacy .vtk, .nrrd/.nhdr, .mha/.mhd, .nii/.nii.gz, or a
/// folder of DICOM slices) as lucent's dense VoxelGrid, spacing per axis: the path by which a
/// ParaView user's CT or MRI scan becomes a medium. Orientation matrices (NIfTI's qform/sform, DICOM's
/// direction cosines) are not applied: the grid is axis-aligned at the file's origin and spacing.
#include <string>
#include <vector>

#include <lucent/scene/voxel_grid.hpp>

namespace lucent::io {

/// Reads one point-data array (`arrayName`, "" = the active scalars or else the first array) as floats;
/// a multi-component array gives its magnitude; NIfTI values are rescaled by the header's slope and
/// intercept. Throws InputError naming the file, the problem (missing, unreadable, no such array,
/// non-positive spacing, empty, too large) and the fix.
scene::VoxelGrid readImageVolume(const std::string& path, const std::string& arrayName = "");

/// The files reading `path` touches: the file, the detached data file its header names, or every
/// file of a DICOM folder. No output may be one of them (cli/output_paths.cpp). Best effort: a
/// header that cannot be read gives the file alone (reading it says why).
std::vector<std::string> volumeInputFiles(const std::string& path);

}  // namespace lucent::io
