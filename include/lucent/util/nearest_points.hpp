#pragma once
/// @file nearest_points.hpp
/// @brief k nearest neighbours among a fixed point set, by a uniform grid of about two points per cell:
/// enough for the Shepard weights between QuadGraph levels, with no tree library.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace lucent::util {

class NearestPoints {
 public:
  explicit NearestPoints(std::vector<glm::dvec3> points) : mPoints(std::move(points)) {
    if (mPoints.empty()) return;
    mLo = mHi = mPoints.front();
    for (const auto& p : mPoints) mLo = glm::min(mLo, p), mHi = glm::max(mHi, p);
    const glm::dvec3 extent = glm::max(mHi - mLo, glm::dvec3(1e-12));
    const double cell = std::cbrt(extent.x * extent.y * extent.z * 2.0 / double(mPoints.size()));
    mCell = std::max({cell, extent.x / 512, extent.y / 512, extent.z / 512, 1e-12});
    mDims = glm::max(glm::ivec3(glm::ceil(extent / mCell)), glm::ivec3(1));
    mStart.assign(std::size_t(mDims.x) * std::size_t(mDims.y) * std::size_t(mDims.z) + 1, 0);
    std::vector<std::size_t> cellOf(mPoints.size());
    for (std::size_t i = 0; i < mPoints.size(); ++i) ++mStart[(cellOf[i] = cellIndex(cellCoord(mPoints[i]))) + 1];
    for (std::size_t c = 1; c < mStart.size(); ++c) mStart[c] += mStart[c - 1];
    mOrder.resize(mPoints.size());
    std::vector<std::size_t> fill(mStart.begin(), mStart.end() - 1);
    for (std::size_t i = 0; i < mPoints.size(); ++i) mOrder[fill[cellOf[i]]++] = std::uint32_t(i);
  }

  /// The k nearest points to p (fewer if the set is smaller), nearest first, as (index, squared distance).
  std::vector<std::pair<std::uint32_t, double>> nearest(const glm::dvec3& p, std::size_t k) const {
    std::vector<std::pair<std::uint32_t, double>> best;
    k = std::min(k, mPoints.size());
    if (k == 0) return best;
    const glm::ivec3 c = cellCoord(p);
    // Grow a cube of cells ring by ring until the k-th distance is inside the searched cube.
    for (int ring = 0;; ++ring) {
      for (int z = c.z - ring; z <= c.z + ring; ++z)
        for (int y = c.y - ring; y <= c.y + ring; ++y)
          for (int x = c.x - ring; x <= c.x + ring; ++x) {
            if (std::max({std::abs(x - c.x), std::abs(y - c.y), std::abs(z - c.z)}) != ring) continue;
            if (x < 0 || y < 0 || z < 0 || x >= mDims.x || y >= mDims.y || z >= mDims.z) continue;
            const std::size_t cell = cellIndex({x, y, z});
            for (std::size_t o = mStart[cell]; o < mStart[cell + 1]; ++o) {
              const std::uint32_t i = mOrder[o];
              const glm::dvec3 d = mPoints[i] - p;
              best.push_back({i, glm::dot(d, d)});
            }
          }
      const auto closer = [](const auto& a, const auto& b) { return a.second < b.second; };
      // Keep the k nearest in linear time, then order them (surface points crowd a volume grid's cells).
      if (best.size() > k) {
        std::nth_element(best.begin(), best.begin() + std::ptrdiff_t(k - 1), best.end(), closer);
        best.resize(k);
      }
      std::sort(best.begin(), best.end(), closer);
      // Every point outside the cube is at least `ring * mCell` away from p (p lies inside cell c).
      const double covered = double(ring) * mCell;
      const bool allCells = ring >= std::max({mDims.x, mDims.y, mDims.z});
      if ((best.size() == k && best.back().second <= covered * covered) || allCells) return best;
    }
  }

  const std::vector<glm::dvec3>& points() const { return mPoints; }

 private:
  glm::ivec3 cellCoord(const glm::dvec3& p) const {
    return glm::clamp(glm::ivec3(glm::floor((p - mLo) / mCell)), glm::ivec3(0), mDims - 1);
  }
  std::size_t cellIndex(const glm::ivec3& c) const {
    return (std::size_t(c.z) * std::size_t(mDims.y) + std::size_t(c.y)) * std::size_t(mDims.x) + std::size_t(c.x);
  }

  std::vector<glm::dvec3> mPoints;
  glm::dvec3 mLo{0}, mHi{0};
  double mCell = 1;
  glm::ivec3 mDims{1};
  std::vector<std::size_t> mStart;
  std::vector<std::uint32_t> mOrder;
};

}  // namespace lucent::util
