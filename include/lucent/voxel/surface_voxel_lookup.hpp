#pragma once
/// @file surface_voxel_lookup.hpp
/// @brief A surface point's surface voxel: the paper's (u, v) -> number map of
/// Mochida et al. 2016 Sec. 2.1, for vertices, texels and the light view's pixels (the
/// voxel-number map). The voxel holding a point on the mesh may be outside (its centre outside the
/// mesh), so the number is the nearest surface voxel's centre, searched in growing boxes around the
/// point's voxel; a point farther than kSearchRadius voxels from every surface voxel (a feature
/// thinner than a voxel that took no voxel) falls back to all of them and is counted.
#include <atomic>
#include <cstdint>
#include <limits>

#include <glm/geometric.hpp>

#include "surface_voxels.hpp"

namespace lucent::voxel {

class SurfaceVoxelLookup {
 public:
  static constexpr int kSearchRadius = 3;

  SurfaceVoxelLookup(const MediaGrid& grid, const SurfaceVoxels& surface)
      : mGrid(grid), mSurface(surface) {}

  /// The number of the surface voxel nearest p; -1 only when there are none.
  std::int32_t numberOf(const glm::dvec3& p) const {
    const glm::ivec3 home = mGrid.voxelOf(p);
    for (int r = 1; r <= kSearchRadius; ++r) {
      const std::int32_t n = nearestInBox(p, home, r);
      if (n >= 0) return n;
    }
    ++mFarPoints;
    std::int32_t best = -1;
    double bestD = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < mSurface.count(); ++i) {
      const double d = distance2(p, mSurface.voxels[i]);
      if (d < bestD) bestD = d, best = std::int32_t(i);
    }
    return best;
  }

  /// Points that found no surface voxel within kSearchRadius voxels (thin features the grid
  /// missed): a resolution too coarse for the shape.
  std::size_t farPoints() const { return mFarPoints; }

 private:
  double distance2(const glm::dvec3& p, const glm::ivec3& v) const {
    const glm::dvec3 d = mGrid.centre(v) - p;
    return glm::dot(d, d);
  }

  std::int32_t nearestInBox(const glm::dvec3& p, const glm::ivec3& home, int r) const {
    std::int32_t best = -1;
    double bestD = std::numeric_limits<double>::infinity();
    for (int z = home.z - r; z <= home.z + r; ++z)
      for (int y = home.y - r; y <= home.y + r; ++y)
        for (int x = home.x - r; x <= home.x + r; ++x) {
          const glm::ivec3 v(x, y, z);
          if (!mGrid.contains(v)) continue;
          const std::int32_t n = mSurface.number[mGrid.index(v)];
          if (n < 0) continue;
          const double d = distance2(p, v);
          if (d < bestD) bestD = d, best = n;
        }
    return best;
  }

  const MediaGrid& mGrid;
  const SurfaceVoxels& mSurface;
  mutable std::atomic<std::size_t> mFarPoints{0};
};

}  // namespace lucent::voxel
