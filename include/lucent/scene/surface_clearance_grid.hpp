#pragma once
/// @file surface_clearance_grid.hpp
/// @brief A lower bound on the distance from a point to the nearest surface of a mesh, from a
/// voxel grid: a random walk deep inside a medium takes many short flights, and one that ends
/// closer than the bound cannot have crossed a surface, so it needs no ray cast (two thirds of a
/// path tracer's time went to them).
///
/// Cells a triangle may touch are marked (its bounding box, less the cells whose centre lies
/// further than half a cell diagonal from its plane); every other cell stores its Chebyshev
/// distance k in cells to the nearest marked one. Any surface point lies in a marked cell, and two
/// cells k apart along some axis are at least (k - 1) h apart, so every point of the cell is at
/// least (k - 1) h from the surface.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "mesh.hpp"

namespace lucent::scene {

class SurfaceClearanceGrid {
 public:
  SurfaceClearanceGrid() = default;
  /// @param cellsAlongLongest  cells along the bounding box's longest side (memory: up to its cube
  ///                           bytes)
  explicit SurfaceClearanceGrid(const TriangleMesh& mesh, int cellsAlongLongest = 128) {
    if (mesh.triangles.empty() || cellsAlongLongest < 1) return;
    const Bounds b = mesh.bounds();
    const glm::dvec3 lo = b.lo, extent = b.hi - b.lo;
    const double longest = std::max(extent.x, std::max(extent.y, extent.z));
    if (!(longest > 0) || !std::isfinite(longest)) return;
    mCell = longest / cellsAlongLongest * (1 + 1e-9);
    mOrigin = lo - glm::dvec3(0.5 * mCell);  // half a cell of margin on every side
    for (int a = 0; a < 3; ++a) mSize[a] = int(std::ceil(extent[a] / mCell)) + 1;
    mSteps.assign(std::size_t(mSize[0]) * mSize[1] * mSize[2], kUnreached);
    markSurfaceCells(mesh);
    spreadChebyshevDistance();
  }

  /// Every point within this distance of p is off the mesh's surfaces (0 when unknown).
  double lowerBound(const glm::dvec3& p) const {
    if (mSteps.empty()) return 0;
    const glm::dvec3 q = (p - mOrigin) / mCell;
    if (!(q.x >= 0 && q.y >= 0 && q.z >= 0)) return 0;  // outside, or NaN
    const int i = int(q.x), j = int(q.y), k = int(q.z);
    if (i >= mSize[0] || j >= mSize[1] || k >= mSize[2]) return 0;
    const std::uint8_t steps = mSteps[index(i, j, k)];
    return steps > 1 ? (steps - 1) * mCell : 0;
  }

  double cellSize() const { return mCell; }

 private:
  static constexpr std::uint8_t kUnreached = 255;  // also the cap: beyond 254 cells, 254

  std::size_t index(int i, int j, int k) const {
    return (std::size_t(k) * mSize[1] + j) * mSize[0] + i;
  }

  void markSurfaceCells(const TriangleMesh& mesh) {
    const double halfDiagonal = 0.5 * std::sqrt(3.0) * mCell;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const glm::uvec3 tri = mesh.triangles[t];
      const glm::dvec3 v0(mesh.positions[tri.x]), v1(mesh.positions[tri.y]),
          v2(mesh.positions[tri.z]);
      const glm::dvec3 area = glm::cross(v1 - v0, v2 - v0);
      const double areaLength = glm::length(area);
      const glm::dvec3 normal = areaLength > 0 ? area / areaLength : glm::dvec3(0);
      int from[3], to[3];
      for (int a = 0; a < 3; ++a) {
        const double lo = std::min(v0[a], std::min(v1[a], v2[a]));
        const double hi = std::max(v0[a], std::max(v1[a], v2[a]));
        from[a] = std::clamp(int(std::floor((lo - mOrigin[a]) / mCell)), 0, mSize[a] - 1);
        to[a] = std::clamp(int(std::floor((hi - mOrigin[a]) / mCell)), 0, mSize[a] - 1);
      }
      for (int k = from[2]; k <= to[2]; ++k)
        for (int j = from[1]; j <= to[1]; ++j)
          for (int i = from[0]; i <= to[0]; ++i) {
            const glm::dvec3 centre = mOrigin + (glm::dvec3(i, j, k) + 0.5) * mCell;
            // A degenerate triangle (no normal) keeps its whole box.
            if (std::abs(glm::dot(centre - v0, normal)) <= halfDiagonal) mSteps[index(i, j, k)] = 0;
          }
    }
  }

  /// Breadth-first from the marked cells over the 26 neighbours: the Chebyshev distance.
  void spreadChebyshevDistance() {
    std::vector<std::uint32_t> front, next;
    for (std::size_t c = 0; c < mSteps.size(); ++c)
      if (mSteps[c] == 0) front.push_back(std::uint32_t(c));
    for (std::uint8_t step = 1; step < kUnreached && !front.empty(); ++step) {
      next.clear();
      for (const std::uint32_t c : front) {
        const int i = int(c % mSize[0]), j = int(c / mSize[0] % mSize[1]),
                  k = int(c / (std::size_t(mSize[0]) * mSize[1]));
        for (int dk = -1; dk <= 1; ++dk)
          for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
              const int ni = i + di, nj = j + dj, nk = k + dk;
              if (ni < 0 || nj < 0 || nk < 0 || ni >= mSize[0] || nj >= mSize[1] || nk >= mSize[2])
                continue;
              std::uint8_t& s = mSteps[index(ni, nj, nk)];
              if (s != kUnreached) continue;
              s = step;
              next.push_back(std::uint32_t(index(ni, nj, nk)));
            }
      }
      front.swap(next);
    }
    // Cells still unreached are 254 or more steps away: 254 is a valid lower bound.
    for (std::uint8_t& s : mSteps)
      if (s == kUnreached) s = kUnreached - 1;
  }

  glm::dvec3 mOrigin{0};
  double mCell = 0;
  int mSize[3] = {0, 0, 0};
  std::vector<std::uint8_t> mSteps;  ///< Chebyshev distance in cells to a surface cell
};

}  // namespace lucent::scene
