#pragma once
/// @file iso_margin.hpp
/// @brief A scan's values as offsets from a threshold, moved off it so that marching cubes builds a
/// closed 2-manifold: every crossing of the threshold lies a margin away from both ends of its grid
/// edge. Without it, a threshold equal to (or within rounding of) a voxel value puts several
/// surface vertices on one grid node: zero-area slivers, and welding them pinches sheets together
/// into edges of four faces (real scans with integer values hit this at almost every threshold).
/// The surface moves by at most the margin (a fraction of a voxel), far below a scan's noise.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include <glm/vec3.hpp>

namespace lucent::scene {

/// The least distance, as a fraction of its grid edge, between an isosurface vertex and either
/// end of the edge. 1 % keeps every triangle's area above ~5e-5 of a voxel face.
inline constexpr double kIsoVertexMargin = 0.01;

namespace detail {
/// The six neighbours' offsets of node `n` of a `dims` grid (x fastest) that exist, into `out`.
inline int gridNeighbours(const glm::ivec3& dims, std::size_t n, std::size_t out[6]) {
  const std::size_t nx = std::size_t(dims.x), nxy = nx * std::size_t(dims.y);
  const std::size_t i = n % nx, j = (n / nx) % std::size_t(dims.y), k = n / nxy;
  int count = 0;
  if (i > 0) out[count++] = n - 1;
  if (i + 1 < nx) out[count++] = n + 1;
  if (j > 0) out[count++] = n - nx;
  if (j + 1 < std::size_t(dims.y)) out[count++] = n + nx;
  if (k > 0) out[count++] = n - nxy;
  if (k + 1 < std::size_t(dims.z)) out[count++] = n + nxy;
  return count;
}

/// The nodes of a `dims` grid (x fastest) with a neighbour on the other side of zero (> 0 is one
/// side, <= 0 the other): the ends of the grid edges a contour at 0 crosses.
inline std::vector<std::size_t> crossingBand(const std::vector<float>& d, const glm::ivec3& dims) {
  std::vector<std::size_t> band;
  std::size_t nb[6];
  for (std::size_t n = 0; n < d.size(); ++n) {
    const int count = gridNeighbours(dims, n, nb);
    for (int c = 0; c < count; ++c)
      if ((d[nb[c]] > 0) != (d[n] > 0)) {
        band.push_back(n);
        break;
      }
  }
  return band;
}
}  // namespace detail

/// Moves the offsets `d` (value minus threshold; > 0 is inside, <= 0 outside) of a `dims` grid, x
/// fastest, off zero in place, keeping each node's side: no offset is 0, and across every grid edge
/// whose ends lie on opposite sides, each end's |d| is at least margin / (1 - margin) of the
/// other's, so the crossing at t = |d0| / (|d0| + |d1|) lies in [margin, 1 - margin] (up to float
/// rounding). Only nodes next to the surface change; the result does not depend on their order
/// beyond rounding, since a raise propagates at margin / (1 - margin) of its size.
inline void keepOffThreshold(std::vector<float>& d, const glm::ivec3& dims,
                             double margin = kIsoVertexMargin) {
  // The smallest magnitude kept: a normal float, so t never divides zero by zero.
  const float floor = std::numeric_limits<float>::min() * 1024.0f;
  for (float& v : d) {
    if (v <= 0 && v > -floor) v = -floor;  // 0 counts as outside, as the check for voxels does
    if (v > 0 && v < floor) v = floor;
  }
  const std::vector<std::size_t> band = detail::crossingBand(d, dims);
  std::size_t nb[6];
  const double ratio = margin / (1.0 - margin);
  for (int pass = 0; pass < 16; ++pass) {  // converges in 2-3 passes: raises shrink by `ratio`
    bool changed = false;
    for (std::size_t n : band) {
      const bool inside = d[n] > 0;
      double need = std::fabs(double(d[n]));
      const int count = detail::gridNeighbours(dims, n, nb);
      for (int c = 0; c < count; ++c)
        if ((d[nb[c]] > 0) != inside) need = std::max(need, ratio * std::fabs(double(d[nb[c]])));
      const float moved = float(inside ? need : -need);
      if (moved != d[n]) d[n] = moved, changed = true;
    }
    if (!changed) break;
  }
}

}  // namespace lucent::scene
