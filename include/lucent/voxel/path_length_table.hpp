#pragma once
/// @file path_length_table.hpp
/// @brief The look-up table of Mochida et al. 2016 Sec. 2.1, stored as the path length
/// through each medium between every pair of a point set (the surface voxels' centres), so that
/// tau(a, b) = sum_m sigma_t[m] length[m] (Eq. 4) follows for any material without a new walk.
///
/// Storage, stated: tau(a, b) = tau(b, a), so only the pairs a <= b are kept, packed row by row
/// (N (N + 1) / 2 entries of one value per medium); each value is fp32, or fp16 in units of the
/// grid's largest voxel edge (relative error at most 2^-11 = 4.9e-4 of the length, so of tau; a
/// unit of the voxel edge keeps any object size inside fp16's range: a grid of 2048 voxels a side
/// spans 3548 units at most, fp16 holds 65504).
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/packing.hpp>

#include "../util/parallel.hpp"
#include "grid_traversal.hpp"

namespace lucent::voxel {

enum class Precision { Half, Single };

inline std::size_t bytesPerValue(Precision p) { return p == Precision::Half ? 2 : 4; }

/// Entries of the symmetric half of an n x n table.
inline std::size_t packedPairs(std::size_t n) { return n * (n + 1) / 2; }

/// The packed position of the pair (a, b), either order.
inline std::size_t pairIndex(std::size_t a, std::size_t b) {
  if (a > b) std::swap(a, b);
  return b * (b + 1) / 2 + a;
}

/// The largest finite fp16 value: a density-weighted length beyond it (density >> 1 over thousands
/// of voxels, tau far past any transmittance) is stored as it rather than as infinity.
inline constexpr double kHalfMax = 65504.0;

class PathLengthTable {
 public:
  /// The memory a table of `points` endpoints and `media` media takes, before building it (in
  /// double: the count of a refused table may not fit 64 bits).
  static double bytesFor(std::size_t points, int media, Precision p) {
    return 0.5 * double(points) * (double(points) + 1) * media * double(bytesPerValue(p));
  }

  /// Walks every pair of `points` through `grid`; media 1..media are stored (0, none, is not).
  PathLengthTable(const MediaGrid& grid, std::vector<glm::dvec3> points, int media, Precision p,
                  const util::ParallelFor& parallelFor = util::serialFor,
                  const util::Progress& progress = {})
      : mPoints(std::move(points)),
        mMedia(media),
        mPrecision(p),
        mUnit(std::max({grid.spacing.x, grid.spacing.y, grid.spacing.z})) {
    if (media < 1 || media > 255) throw std::invalid_argument("path length table: 1..255 media");
    const std::size_t n = mPoints.size(), values = packedPairs(n) * std::size_t(media);
    if (p == Precision::Half)
      mHalf.assign(values, 0);
    else
      mSingle.assign(values, 0.f);
    std::atomic<std::size_t> done{0};
    // Row b holds b + 1 pairs: taking rows from both ends in turn evens out the chunks.
    parallelFor(n, [&](std::size_t begin, std::size_t end) {
      for (std::size_t r = begin; r < end; ++r) {
        const std::size_t b = r % 2 == 0 ? r / 2 : n - 1 - r / 2;
        for (std::size_t a = 0; a <= b; ++a) store(pairIndex(a, b), grid, mPoints[a], mPoints[b]);
        if (progress) progress(double(done += b + 1) / double(packedPairs(n)));
      }
    });
  }

  /// Path length (mm, at density 1) through media 1..media from point a to point b.
  void lengths(std::size_t a, std::size_t b, float* out) const {
    const std::size_t base = pairIndex(a, b) * std::size_t(mMedia);
    for (int m = 0; m < mMedia; ++m)
      out[m] = mPrecision == Precision::Half
                   ? float(glm::unpackHalf1x16(mHalf[base + std::size_t(m)]) * mUnit)
                   : mSingle[base + std::size_t(m)];
  }

  std::size_t points() const { return mPoints.size(); }
  const glm::dvec3& point(std::size_t i) const { return mPoints[i]; }
  int media() const { return mMedia; }
  std::size_t bytes() const { return mHalf.size() * 2 + mSingle.size() * 4; }

  ///@{ The stored values, packed by pairIndex then medium, for an upload (the GPU twin): fp16 in
  /// units of halfUnit() mm, or fp32 mm; the other vector is empty.
  Precision precision() const { return mPrecision; }
  const std::vector<std::uint16_t>& halfValues() const { return mHalf; }
  const std::vector<float>& singleValues() const { return mSingle; }
  double halfUnit() const { return mUnit; }
  ///@}

 private:
  void store(std::size_t pair, const MediaGrid& grid, const glm::dvec3& a, const glm::dvec3& b) {
    double length[256] = {};
    addPathLengths(grid, a, b, mMedia + 1, length);
    const std::size_t base = pair * std::size_t(mMedia);
    for (int m = 0; m < mMedia; ++m) {
      const double l = length[m + 1];
      if (mPrecision == Precision::Half)
        mHalf[base + std::size_t(m)] = glm::packHalf1x16(float(std::min(l / mUnit, kHalfMax)));
      else
        mSingle[base + std::size_t(m)] = float(l);
    }
  }

  std::vector<glm::dvec3> mPoints;
  int mMedia;
  Precision mPrecision;
  double mUnit;  ///< the fp16 values' unit: the largest voxel edge (mm)
  std::vector<std::uint16_t> mHalf;
  std::vector<float> mSingle;
};

}  // namespace lucent::voxel
