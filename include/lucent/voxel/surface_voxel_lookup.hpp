#pragma once
/// @file surface_voxel_lookup.hpp
/// @brief A surface point's surface voxel: the paper's (u, v) -> number map of Mochida et al. 2016
/// Sec. 2.1, for vertices, texels and the light view's pixels (the voxel-number map). The voxel
/// holding a point on the mesh may be outside (its centre outside the mesh), so the number is the
/// surface voxel with the nearest centre among the 3 x 3 x 3 voxels around the point; where none is
/// there (a feature thinner than a voxel that took no voxel), a map built once by a multi-source
/// flood fill over the grid gives the nearest surface voxel, and the point is counted.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <deque>
#include <limits>

#include <glm/geometric.hpp>

#include "surface_voxels.hpp"

namespace lucent::voxel {

class SurfaceVoxelLookup {
 public:
  /// Points farther than this many voxel edges from every surface voxel are counted (farPoints).
  static constexpr int kSearchRadius = 3;

  SurfaceVoxelLookup(const MediaGrid& grid, const SurfaceVoxels& surface)
      : mGrid(grid), mSurface(surface), mNearest(nearestSurfaceVoxels(grid, surface)) {}

  /// The number of the surface voxel nearest p; -1 only when there are none.
  std::int32_t numberOf(const glm::dvec3& p) const {
    if (mSurface.count() == 0) return -1;
    const glm::ivec3 home = glm::clamp(mGrid.voxelOf(p), glm::ivec3(0), mGrid.dims - 1);
    std::int32_t best = -1;
    double bestD = std::numeric_limits<double>::infinity();
    for (int z = home.z - 1; z <= home.z + 1; ++z)
      for (int y = home.y - 1; y <= home.y + 1; ++y)
        for (int x = home.x - 1; x <= home.x + 1; ++x) {
          const glm::ivec3 v(x, y, z);
          if (!mGrid.contains(v)) continue;
          const std::int32_t n = mSurface.number[mGrid.index(v)];
          if (n >= 0 && distance2(p, n) < bestD) bestD = distance2(p, n), best = n;
        }
    if (best >= 0) return best;
    best = mNearest[mGrid.index(home)];
    const double edge = std::max({mGrid.spacing.x, mGrid.spacing.y, mGrid.spacing.z});
    if (distance2(p, best) > kSearchRadius * kSearchRadius * edge * edge) ++mFarPoints;
    return best;
  }

  /// Points more than kSearchRadius voxels from every surface voxel since the last reset (thin
  /// features the grid missed): a resolution too coarse for the shape.
  std::size_t farPoints() const { return mFarPoints; }
  void resetFarPoints() { mFarPoints = 0; }

  /// Per grid voxel, the surface voxel its flood fill reached (for an upload: the GPU twin).
  const std::vector<std::int32_t>& nearestMap() const { return mNearest; }

 private:
  double distance2(const glm::dvec3& p, std::int32_t n) const {
    const glm::dvec3 d = mGrid.centre(mSurface.voxels[std::size_t(n)]) - p;
    return glm::dot(d, d);
  }

  /// Per grid voxel, a surface voxel with a near centre: seeded at the surface voxels and spread to
  /// the 26 neighbours, a voxel taking a neighbour's source when that source is nearer than its
  /// own.
  static std::vector<std::int32_t> nearestSurfaceVoxels(const MediaGrid& grid,
                                                        const SurfaceVoxels& surface) {
    std::vector<std::int32_t> nearest(grid.voxelCount(), -1);
    std::deque<glm::ivec3> open;
    for (std::size_t i = 0; i < surface.count(); ++i) {
      nearest[grid.index(surface.voxels[i])] = std::int32_t(i);
      open.push_back(surface.voxels[i]);
    }
    auto d2 = [&](const glm::ivec3& v, std::int32_t n) {
      const glm::dvec3 d = grid.centre(v) - grid.centre(surface.voxels[std::size_t(n)]);
      return glm::dot(d, d);
    };
    while (!open.empty()) {
      const glm::ivec3 v = open.front();
      open.pop_front();
      const std::int32_t source = nearest[grid.index(v)];
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const glm::ivec3 u = v + glm::ivec3(dx, dy, dz);
            if (!grid.contains(u)) continue;
            std::int32_t& mine = nearest[grid.index(u)];
            if (mine >= 0 && d2(u, mine) <= d2(u, source)) continue;
            mine = source;
            open.push_back(u);
          }
    }
    return nearest;
  }

  const MediaGrid& mGrid;
  const SurfaceVoxels& mSurface;
  std::vector<std::int32_t> mNearest;
  mutable std::atomic<std::size_t> mFarPoints{0};
};

}  // namespace lucent::voxel
