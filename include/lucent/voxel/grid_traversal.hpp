#pragma once
/// @file grid_traversal.hpp
/// @brief The exact walk of a segment through a MediaGrid (Amanatides and Woo, "A Fast Voxel
/// Traversal Algorithm for Ray Tracing", Eurographics 1987), and the path length through each
/// medium it gives. With the lengths, the optical thickness of Eq. 4 of
/// Mochida et al. 2016, tau(x_in, x_out) = int sigma_t dx, is sum_m sigma_t[m] length[m]:
/// exact for piecewise-constant media, and a material edit recomputes no walk.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

#include "media_grid.hpp"

namespace lucent::voxel {

/// The parameter interval [t0, t1] of a + t (b - a), t in [0, 1], inside the grid's box (slab
/// test); false when the segment misses it.
inline bool clipToGrid(const MediaGrid& grid, const glm::dvec3& a, const glm::dvec3& b, double& t0,
                       double& t1) {
  t0 = 0, t1 = 1;
  const glm::dvec3 d = b - a, lo = grid.lowerCorner(), hi = grid.upperCorner();
  if (d.x == 0 && d.y == 0 && d.z == 0) return false;  // a point crosses nothing
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0) {
      if (a[k] < lo[k] || a[k] > hi[k]) return false;
      continue;
    }
    double enter = (lo[k] - a[k]) / d[k], leave = (hi[k] - a[k]) / d[k];
    if (enter > leave) std::swap(enter, leave);
    t0 = std::max(t0, enter), t1 = std::min(t1, leave);
  }
  return t0 < t1;
}

/// Calls visit(voxel, t0, t1) for every voxel of the grid the segment a -> b crosses, in order from
/// a, with the segment's parameter interval inside it; the intervals tile the clipped segment
/// exactly (each starts where the last ended).
template <class Visit>
void traverse(const MediaGrid& grid, const glm::dvec3& a, const glm::dvec3& b, Visit&& visit) {
  if (grid.voxelCount() == 0) return;
  double t = 0, tEnd = 0;
  if (!clipToGrid(grid, a, b, t, tEnd)) return;
  const glm::dvec3 d = b - a;
  // The entry point's voxel. On a boundary floor may pick the voxel behind; the first step then
  // leaves it at zero length, unvisited.
  glm::ivec3 v = glm::clamp(grid.voxelOf(a + d * t), glm::ivec3(0), grid.dims - 1);
  glm::ivec3 step(0);
  glm::dvec3 tNext(std::numeric_limits<double>::infinity()), tDelta(tNext);
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0) continue;
    step[k] = d[k] > 0 ? 1 : -1;
    tDelta[k] = grid.spacing[k] / std::abs(d[k]);
    const double boundary = grid.origin[k] + double(v[k] + (step[k] > 0 ? 1 : 0)) * grid.spacing[k];
    tNext[k] = (boundary - a[k]) / d[k];
  }
  // A voxel count bound: a walk crosses at most dims.x + dims.y + dims.z boundaries.
  const long long maxSteps = 4LL + grid.dims.x + grid.dims.y + grid.dims.z;
  for (long long i = 0; i < maxSteps && t < tEnd; ++i) {
    const int axis =
        tNext.x <= tNext.y ? (tNext.x <= tNext.z ? 0 : 2) : (tNext.y <= tNext.z ? 1 : 2);
    const double leave = std::min(tNext[axis], tEnd);
    if (leave > t) visit(v, t, leave);
    t = std::max(t, leave);
    v[axis] += step[axis];
    // Recomputed from the index, not accumulated: no drift over thousands of voxels.
    const double boundary =
        grid.origin[axis] + double(v[axis] + (step[axis] > 0 ? 1 : 0)) * grid.spacing[axis];
    tNext[axis] = (boundary - a[axis]) / d[axis];
    if (!grid.contains(v)) break;
  }
}

/// Adds the path length (mm) through each medium 0..media-1 along a -> b to out[0..media-1],
/// weighted by the voxels' density (a length at density 1). Allocates nothing: the per-query walk
/// of on-the-fly marching.
inline void addPathLengths(const MediaGrid& grid, const glm::dvec3& a, const glm::dvec3& b,
                           int media, double* out) {
  const double total = glm::length(b - a);
  traverse(grid, a, b, [&](const glm::ivec3& v, double t0, double t1) {
    const std::size_t i = grid.index(v);
    const std::uint8_t m = grid.medium[i];
    if (m < media) out[m] += (t1 - t0) * total * grid.densityAt(i);
  });
}

/// Path length through each medium 0..media-1 along a -> b (addPathLengths); medium 0 (none)
/// included, so with no density the lengths add up to the part of the segment inside the grid.
inline std::vector<double> pathLengths(const MediaGrid& grid, const glm::dvec3& a,
                                       const glm::dvec3& b, int media) {
  std::vector<double> length(std::size_t(std::max(media, 1)), 0.0);
  addPathLengths(grid, a, b, int(length.size()), length.data());
  return length;
}

/// tau = sum_m sigma_t[m] length[m] (Eq. 4), one channel; sigmaT[0] is normally 0 (no medium).
inline double opticalThickness(const std::vector<double>& length,
                               const std::vector<double>& sigmaT) {
  double tau = 0;
  for (std::size_t m = 0; m < length.size() && m < sigmaT.size(); ++m) tau += sigmaT[m] * length[m];
  return tau;
}

}  // namespace lucent::voxel
