#pragma once
/// @file voxelize.hpp
/// @brief Closed meshes into a MediaGrid, exactly: a voxel takes a medium when its centre lies
/// inside the mesh. Nested meshes become inner media and cavities by filling in order (the object
/// with 1, a cavity with kNoMedium, an inclusion with 2: the later wins).
///
/// For every row of voxel centres along x, the row's line crosses the mesh where it pierces a
/// triangle's y-z projection; each crossing carries the sign of the triangle's normal x, so the
/// winding number between crossings says inside (non-zero) or outside, whatever the nesting. A line
/// through an edge or a vertex is counted once by a half-open rule on the projected edges, so a
/// closed mesh stays watertight even when rows pass exactly through its vertices.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "../scene/mesh.hpp"
#include "media_grid.hpp"

namespace lucent::voxel {

namespace detail {
/// Whether the y-z point q lies in the counter-clockwise projected triangle (a, b, c); a point on
/// an edge belongs to the triangle on the edge's left when the edge runs up (dy > 0), or runs along
/// z towards -z: two triangles sharing the edge traverse it in opposite directions, so exactly one
/// takes it.
inline bool coversPoint(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c,
                        const glm::dvec2& q) {
  const glm::dvec2 corners[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    const glm::dvec2 p = corners[k], e = corners[(k + 1) % 3] - p;
    const double side = e.x * (q.y - p.y) - e.y * (q.x - p.x);  // > 0: q left of the edge
    if (side > 0) continue;
    if (side < 0) return false;
    const bool owns = e.x > 0 || (e.x == 0 && e.y < 0);
    if (!owns) return false;
  }
  return true;
}

/// floor/ceil of a voxel coordinate clamped to [lo, hi] before the int conversion (a triangle far
/// outside the grid must not overflow it).
inline int clampedIndex(double v, int lo, int hi) {
  return int(std::clamp(v, double(lo), double(hi)));
}

struct Crossing {
  double x;
  int sign;  ///< +1 where the mesh's outward normal points to +x (leaving), -1 entering
  bool operator<(const Crossing& o) const { return x < o.x; }
};
}  // namespace detail

/// Sets `medium` in every voxel of `grid` whose centre is inside the closed, outward `mesh`.
inline void fillInside(MediaGrid& grid, const scene::TriangleMesh& mesh, std::uint8_t medium) {
  if (grid.voxelCount() == 0) return;
  const std::size_t rows = std::size_t(grid.dims.y) * std::size_t(grid.dims.z);
  std::vector<std::vector<detail::Crossing>> crossings(rows);
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 p0(mesh.positions[t.x]), p1(mesh.positions[t.y]), p2(mesh.positions[t.z]);
    const glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
    if (n.x == 0) continue;  // parallel to the rows: its neighbours carry the crossing
    // The projection (y, z), counter-clockwise when n.x > 0; reorder the others so.
    glm::dvec2 a(p0.y, p0.z), b(p1.y, p1.z), c(p2.y, p2.z);
    if (n.x < 0) std::swap(b, c);
    const glm::dvec2 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
    // The rows whose centre (j + 1/2, k + 1/2) lies in the projection's bounding box.
    const auto first = [](double v, int n) {
      return detail::clampedIndex(std::ceil(v - 0.5), 0, n);
    };
    const auto last = [](double v, int n) {
      return detail::clampedIndex(std::floor(v - 0.5), -1, n - 1);
    };
    const int j0 = first((lo.x - grid.origin.y) / grid.spacing.y, grid.dims.y);
    const int j1 = last((hi.x - grid.origin.y) / grid.spacing.y, grid.dims.y);
    const int k0 = first((lo.y - grid.origin.z) / grid.spacing.z, grid.dims.z);
    const int k1 = last((hi.y - grid.origin.z) / grid.spacing.z, grid.dims.z);
    for (int k = k0; k <= k1; ++k)
      for (int j = j0; j <= j1; ++j) {
        const glm::dvec2 q(grid.origin.y + (j + 0.5) * grid.spacing.y,
                           grid.origin.z + (k + 0.5) * grid.spacing.z);
        if (!detail::coversPoint(a, b, c, q)) continue;
        // The plane n . (p - p0) = 0 at (y, z) = q.
        const double x = p0.x - (n.y * (q.x - p0.y) + n.z * (q.y - p0.z)) / n.x;
        crossings[std::size_t(k) * std::size_t(grid.dims.y) + std::size_t(j)].push_back(
            {x, n.x > 0 ? 1 : -1});
      }
  }
  for (int k = 0; k < grid.dims.z; ++k)
    for (int j = 0; j < grid.dims.y; ++j) {
      auto& row = crossings[std::size_t(k) * std::size_t(grid.dims.y) + std::size_t(j)];
      if (row.empty()) continue;
      std::sort(row.begin(), row.end());
      // Sweep the centres in x; the winding number is minus the sum of the signs passed (entering
      // crossings have normal x < 0).
      int winding = 0;
      std::size_t next = 0;
      for (int i = 0; i < grid.dims.x; ++i) {
        const double x = grid.origin.x + (i + 0.5) * grid.spacing.x;
        while (next < row.size() && row[next].x <= x) winding -= row[next++].sign;
        if (winding != 0) grid.set({i, j, k}, medium);
      }
    }
}

/// The voxel edge and the voxels inside the box of a grid fitted around `mesh` (gridAround).
inline double gridVoxelEdge(const scene::TriangleMesh& mesh, int voxelsAlongLongest) {
  const scene::Bounds box = mesh.bounds();
  const glm::dvec3 extent = box.hi - box.lo;
  const double longest = std::max({extent.x, extent.y, extent.z});
  return longest > 0 ? longest / std::max(1, voxelsAlongLongest) : 1.0;
}

/// The dimensions gridAround gives, computed without allocating (so they can be bounded first).
inline glm::ivec3 gridDimsAround(const scene::TriangleMesh& mesh, int voxelsAlongLongest) {
  const scene::Bounds box = mesh.bounds();
  const double h = gridVoxelEdge(mesh, voxelsAlongLongest);
  return glm::max(glm::ivec3(glm::ceil((box.hi - box.lo) / h)), glm::ivec3(1)) + 2;
}

/// A grid fitted around a mesh's bounding box with `voxelsAlongLongest` voxels on its longest side
/// (cubic voxels) and one empty voxel of margin all round, so the outside touches every side.
inline MediaGrid gridAround(const scene::TriangleMesh& mesh, int voxelsAlongLongest) {
  const scene::Bounds box = mesh.bounds();
  const glm::dvec3 extent = box.hi - box.lo;
  const double h = gridVoxelEdge(mesh, voxelsAlongLongest);
  const glm::ivec3 dims = gridDimsAround(mesh, voxelsAlongLongest);
  return MediaGrid(dims, box.lo - h - 0.5 * (glm::dvec3(dims - 2) * h - extent), glm::dvec3(h));
}

}  // namespace lucent::voxel
