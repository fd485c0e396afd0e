#pragma once
/// @file surface_voxels.hpp
/// @brief The surface voxels of Mochida et al. 2016 Sec. 2.1, extracted and numbered: the
/// voxels of a medium that touch the outside (a face neighbour that is no medium and connected to
/// the grid's border, or the border itself). A cavity's wall is not surface: light reaches a cavity
/// only through the medium. The numbers index the LUT's rows and columns.
#include <cstdint>
#include <deque>
#include <vector>

#include "media_grid.hpp"

namespace lucent::voxel {

/// Which voxels are outside: no medium and face-connected to the grid's border (a flood fill).
inline std::vector<bool> outsideVoxels(const MediaGrid& grid) {
  std::vector<bool> outside(grid.voxelCount(), false);
  std::deque<glm::ivec3> open;
  auto reach = [&](const glm::ivec3& v) {
    if (!grid.contains(v) || grid.at(v) != kNoMedium || outside[grid.index(v)]) return;
    outside[grid.index(v)] = true;
    open.push_back(v);
  };
  for (int z = 0; z < grid.dims.z; ++z)
    for (int y = 0; y < grid.dims.y; ++y)
      for (int x = 0; x < grid.dims.x; ++x)
        if (x == 0 || y == 0 || z == 0 || x == grid.dims.x - 1 || y == grid.dims.y - 1 ||
            z == grid.dims.z - 1)
          reach({x, y, z});
  static const glm::ivec3 kFaces[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                       {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  while (!open.empty()) {
    const glm::ivec3 v = open.front();
    open.pop_front();
    for (const auto& f : kFaces) reach(v + f);
  }
  return outside;
}

struct SurfaceVoxels {
  std::vector<glm::ivec3> voxels;    ///< in grid order (x fastest): number i is voxels[i]
  std::vector<std::int32_t> number;  ///< per grid voxel: its surface number, or -1
  std::size_t count() const { return voxels.size(); }
};

inline SurfaceVoxels surfaceVoxels(const MediaGrid& grid) {
  SurfaceVoxels s;
  s.number.assign(grid.voxelCount(), -1);
  const std::vector<bool> outside = outsideVoxels(grid);
  static const glm::ivec3 kFaces[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                       {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  for (int z = 0; z < grid.dims.z; ++z)
    for (int y = 0; y < grid.dims.y; ++y)
      for (int x = 0; x < grid.dims.x; ++x) {
        const glm::ivec3 v(x, y, z);
        if (grid.at(v) == kNoMedium) continue;
        bool touches = false;
        for (const auto& f : kFaces) touches |= !grid.contains(v + f) || outside[grid.index(v + f)];
        if (!touches) continue;
        s.number[grid.index(v)] = std::int32_t(s.voxels.size());
        s.voxels.push_back(v);
      }
  return s;
}

}  // namespace lucent::voxel
