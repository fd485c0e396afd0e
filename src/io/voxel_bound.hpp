#pragma once
/// @file voxel_bound.hpp
/// @brief The one check of scene::kMaxVoxels for every volume reader (VTK image data, OpenVDB),
/// with the bound in its message derived from the constant.
#include <cmath>
#include <cstdio>
#include <string>

#include <lucent/scene/voxel_grid.hpp>
#include <lucent/util/number_text.hpp>

#include "../util/error.hpp"

namespace lucent::io {

/// A number from a file's header as a message shows it (util/number_text.hpp).
using util::numberShown;

/// Throws InputError "<subject>W x H x D voxels, more than lucent <verb> (<bound>, <GB> GB); <fix>"
/// when dims (doubles: a hostile extent can exceed int) hold more than scene::kMaxVoxels.
inline void checkVoxelCount(const std::string& subject, const double dims[3],
                            const std::string& verb, const std::string& fix) {
  if (!(dims[0] * dims[1] * dims[2] > scene::kMaxVoxels)) return;
  char bound[64];
  std::snprintf(bound, sizeof bound, "%g, %g GB", scene::kMaxVoxels,
                scene::kMaxVoxels * sizeof(float) / 1e9);
  throw InputError(subject + numberShown(dims[0]) + " x " + numberShown(dims[1]) + " x " +
                   numberShown(dims[2]) + " voxels, more than lucent " + verb + " (" + bound +
                   "); " + fix);
}

}  // namespace lucent::io
