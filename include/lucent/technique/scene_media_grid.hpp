#pragma once
/// @file scene_media_grid.hpp
/// @brief A scene's media as a voxel grid (voxel/media_grid.hpp): what the voxel techniques
/// (taulut, voxel-single) discretise.
#include <cmath>
#include <string>

#include "../voxel/voxelize.hpp"
#include "knob.hpp"
#include "scene.hpp"

namespace lucent::technique::detail {

/// The scene as media: the object is medium 1, inclusion i is medium 2 + i (filled after the
/// object, so it wins), a cavity (the mesh's inward shells) is none; density fields sampled at the
/// voxel centres.
/// The most voxels a voxel technique's grid may hold: with its surface numbering (4 bytes), density
/// (4) and nearest-surface map (4), 13 bytes each, 1.3 GB. Checked before allocating.
inline constexpr double kMaxGridVoxels = 1e8;

inline voxel::MediaGrid mediaGridOf(const SceneDescription& scene, int voxelsAlongLongest) {
  if (scene.inclusions.size() > 254)
    throw RequestError(
        "the voxel techniques take at most 254 inclusions (the grid stores a byte per voxel)");
  const glm::ivec3 dims = voxel::gridDimsAround(scene.mesh, voxelsAlongLongest);
  const double count = double(dims.x) * double(dims.y) * double(dims.z);
  if (count > kMaxGridVoxels)
    throw RequestError("voxels=" + std::to_string(voxelsAlongLongest) + " makes a grid of " +
                       std::to_string(dims.x) + " x " + std::to_string(dims.y) + " x " +
                       std::to_string(dims.z) + " voxels, more than the " +
                       std::to_string(int(kMaxGridVoxels / 1e6)) +
                       " million the voxel techniques hold; lower voxels");
  voxel::MediaGrid grid = voxel::gridAround(scene.mesh, voxelsAlongLongest);
  voxel::fillInside(grid, scene.mesh, 1);
  for (std::size_t i = 0; i < scene.inclusions.size(); ++i)
    voxel::fillInside(grid, scene.inclusions[i].surface, std::uint8_t(2 + i));
  bool heterogeneous = scene.medium.heterogeneous();
  for (const auto& inc : scene.inclusions) heterogeneous |= inc.medium.heterogeneous();
  if (!heterogeneous) return grid;
  grid.density.assign(grid.voxelCount(), 1.f);
  for (int z = 0; z < grid.dims.z; ++z)
    for (int y = 0; y < grid.dims.y; ++y)
      for (int x = 0; x < grid.dims.x; ++x) {
        const std::size_t i = grid.index({x, y, z});
        const std::uint8_t m = grid.medium[i];
        if (m == voxel::kNoMedium) continue;
        const Medium& medium = m == 1 ? scene.medium : scene.inclusions[m - 2u].medium;
        if (!medium.density) continue;
        const double d = medium.density(grid.centre({x, y, z}));
        if (!(d >= 0 && std::isfinite(d)))
          throw RequestError("the density of " + medium.densityDescription + " is " +
                             std::to_string(d) +
                             " at a voxel centre; densities must be finite "
                             "and >= 0");
        grid.density[i] = float(d);
      }
  return grid;
}

}  // namespace lucent::technique::detail
