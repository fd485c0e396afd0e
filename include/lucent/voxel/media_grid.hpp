#pragma once
/// @file media_grid.hpp
/// @brief Which medium fills each voxel of a box-shaped grid: the voxel optical-thickness LUT's
/// (Mochida et al. 2016 Sec. 2.1) discretised object. Voxels are boxes with their own
/// spacing per axis (scans are anisotropic); 0 is no medium (outside the object, or a cavity), 1..
/// are media whose coefficients live elsewhere, so a material edit changes no grid. An optional
/// density per voxel scales its medium's coefficients (a scan; 1 where absent).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace lucent::voxel {

/// The medium index of "nothing": outside the object or inside a cavity.
inline constexpr std::uint8_t kNoMedium = 0;

struct MediaGrid {
  glm::ivec3 dims{0};
  glm::dvec3 origin{0};              ///< the lower corner of voxel (0, 0, 0), mm
  glm::dvec3 spacing{1};             ///< voxel edge per axis, mm
  std::vector<std::uint8_t> medium;  ///< x fastest, then y, then z
  std::vector<float> density;        ///< empty, or one multiplier per voxel (same order)

  MediaGrid() = default;
  MediaGrid(glm::ivec3 size, glm::dvec3 lowerCorner, glm::dvec3 voxelSize,
            std::uint8_t fill = kNoMedium)
      : dims(glm::max(size, glm::ivec3(0))),
        origin(lowerCorner),
        spacing(voxelSize),
        medium(voxelCount(), fill) {}

  std::size_t voxelCount() const {
    return std::size_t(dims.x) * std::size_t(dims.y) * std::size_t(dims.z);
  }
  bool contains(const glm::ivec3& v) const {
    return v.x >= 0 && v.y >= 0 && v.z >= 0 && v.x < dims.x && v.y < dims.y && v.z < dims.z;
  }
  std::size_t index(const glm::ivec3& v) const {
    return (std::size_t(v.z) * std::size_t(dims.y) + std::size_t(v.y)) * std::size_t(dims.x) +
           std::size_t(v.x);
  }
  std::uint8_t at(const glm::ivec3& v) const { return contains(v) ? medium[index(v)] : kNoMedium; }
  void set(const glm::ivec3& v, std::uint8_t m) { medium[index(v)] = m; }
  /// The coefficient multiplier of an in-grid voxel.
  double densityAt(std::size_t i) const { return density.empty() ? 1.0 : double(density[i]); }

  glm::dvec3 lowerCorner() const { return origin; }
  glm::dvec3 upperCorner() const { return origin + glm::dvec3(dims) * spacing; }
  glm::dvec3 centre(const glm::ivec3& v) const { return origin + (glm::dvec3(v) + 0.5) * spacing; }
  /// The voxel holding p (it may lie outside the grid; `contains` tells).
  glm::ivec3 voxelOf(const glm::dvec3& p) const {
    const glm::dvec3 u = glm::floor((p - origin) / spacing);
    return glm::ivec3(glm::clamp(u, glm::dvec3(-1), glm::dvec3(dims)));  // no int overflow
  }
};

}  // namespace lucent::voxel
