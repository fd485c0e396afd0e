#pragma once
/// @file voxel_grid.hpp
/// @brief A dense scalar voxel grid in millimetres: a scanned or simulated density (from OpenVDB or
/// vtkImageData) that heterogeneous techniques sample. Values sit at voxel centres.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace lucent::scene {

/// The most voxels a reader densifies (4 bytes each: 2 GB); readers check it from the file's
/// header, before allocating.
inline constexpr double kMaxVoxels = 5e8;

/// Voxel spacing a scan may have (millimetres: a nanometre to a kilometre), and the largest ratio
/// between its axes: beyond these a scan's isosurface degenerates into zero-area triangles.
inline constexpr double kMinVoxelSpacing = 1e-6;
inline constexpr double kMaxVoxelSpacing = 1e6;
inline constexpr double kMaxSpacingRatio = 1000;

/// Why `spacing` is not a scan's (empty when it is): one rule for every reader.
inline std::string spacingProblem(const double spacing[3]) {
  const char* axis[3] = {"x", "y", "z"};
  char text[160];
  for (int a = 0; a < 3; ++a)
    if (!(spacing[a] >= kMinVoxelSpacing && spacing[a] <= kMaxVoxelSpacing)) {
      std::snprintf(text, sizeof text,
                    "the voxel spacing along %s is %.6g; spacing must lie in [%g, %g] (mm)",
                    axis[a], spacing[a], kMinVoxelSpacing, kMaxVoxelSpacing);
      return text;
    }
  const double lo = std::min({spacing[0], spacing[1], spacing[2]});
  const double hi = std::max({spacing[0], spacing[1], spacing[2]});
  if (hi > kMaxSpacingRatio * lo) {
    std::snprintf(text, sizeof text,
                  "the voxel spacing (%.6g, %.6g, %.6g) differs more than %gx between axes",
                  spacing[0], spacing[1], spacing[2], kMaxSpacingRatio);
    return text;
  }
  return "";
}

struct VoxelGrid {
  glm::ivec3 dims{0};
  glm::dvec3 origin{0};       ///< centre of voxel (0,0,0), mm
  glm::dvec3 spacing{1};      ///< voxel edge per axis, mm (scans are often anisotropic)
  std::vector<float> values;  ///< x fastest, then y, then z

  std::size_t index(int i, int j, int k) const {
    return (std::size_t(k) * std::size_t(dims.y) + std::size_t(j)) * std::size_t(dims.x) +
           std::size_t(i);
  }
  float at(int i, int j, int k) const { return values[index(i, j, k)]; }

  /// Trilinear interpolation at a position (mm); outside the grid the nearest boundary value
  /// (clamped).
  double sample(const glm::dvec3& p) const {
    if (values.empty()) return 0;
    const glm::dvec3 u = glm::clamp((p - origin) / spacing, glm::dvec3(0), glm::dvec3(dims - 1));
    const glm::ivec3 i0 = glm::min(glm::ivec3(u), glm::max(dims - 2, glm::ivec3(0)));
    const glm::ivec3 i1 = glm::min(i0 + 1, dims - 1);
    const glm::dvec3 t = u - glm::dvec3(i0);
    double v = 0;
    for (int c = 0; c < 8; ++c) {
      const int x = c & 1 ? i1.x : i0.x, y = c & 2 ? i1.y : i0.y, z = c & 4 ? i1.z : i0.z;
      const double w = (c & 1 ? t.x : 1 - t.x) * (c & 2 ? t.y : 1 - t.y) * (c & 4 ? t.z : 1 - t.z);
      v += w * double(at(x, y, z));
    }
    return v;
  }
};

}  // namespace lucent::scene
