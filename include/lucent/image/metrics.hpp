#pragma once
/// @file metrics.hpp
/// @brief Image error metrics of DESIGN.md: RMSE of tone-mapped images (what the papers report),
/// relative RMS error of linear radiance over covered pixels, and the largest absolute error.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "tonemap.hpp"

namespace lucent::image {

struct ImageErrors {
  double rmseToneMapped =
      0;                   ///< over all pixels and channels, both mapped with the reference's L_avg
  double relativeRms = 0;  ///< sqrt(sum |a-b|^2 / sum |b|^2) over pixels covered in either image
  double maxAbsError = 0;  ///< largest per-channel |a-b| of linear radiance
  std::size_t coveredPixels = 0;
  std::size_t coverageMismatch = 0;  ///< pixels covered in one image only
  double meanRatio[3] = {
      0, 0, 0};  ///< per channel: sum of test / sum of reference over covered pixels (bias)
  /// The relative RMS error left after each channel of the test is scaled by its least-squares
  /// factor sum(ab) / sum(a^2): the error of the image's shape, which no normalisation removes.
  double scaledRelativeRms = 0;
};

/// sqrt(sum |a - b|^2 / sum |b|^2) of per-point radiance (vertices, request points): the
/// relative RMS of `test` against `reference`, as ImageErrors::relativeRms is over pixels.
inline double relativeRms(const std::vector<glm::dvec3>& test,
                          const std::vector<glm::dvec3>& reference) {
  double diff = 0, ref = 0;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    const glm::dvec3 d = test[i] - reference[i];
    diff += glm::dot(d, d), ref += glm::dot(reference[i], reference[i]);
  }
  return std::sqrt(diff / ref);
}

inline void requireSameSize(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("images differ in size: " + std::to_string(a.width) + "x" +
                                std::to_string(a.height) + " against " + std::to_string(b.width) +
                                "x" + std::to_string(b.height) +
                                "; render both at the same --width/--height");
}

/// Errors of display values (already tone-mapped, e.g. read from PNG): RMSE of the values as they
/// are.
inline ImageErrors compareDisplayImages(const Image& test, const Image& reference) {
  requireSameSize(test, reference);
  ImageErrors e;
  double sq = 0;
  for (std::size_t i = 0; i < reference.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = double(test.pixels[i][c]) - double(reference.pixels[i][c]);
      sq += d * d;
      e.maxAbsError = std::max(e.maxAbsError, std::abs(d));
    }
  e.coveredPixels = reference.pixels.size();
  e.rmseToneMapped =
      reference.pixels.empty() ? 0 : std::sqrt(sq / (3.0 * double(reference.pixels.size())));
  return e;
}

/// Errors of `test` against `reference`; both must have the same size.
inline ImageErrors compareImages(const Image& test, const Image& reference, ToneMap toneMap = {}) {
  requireSameSize(test, reference);
  ImageErrors e;
  if (toneMap.kind == ToneMap::Kind::Paper && !(toneMap.averageRadiance > 0))
    toneMap.averageRadiance = meanCoveredLuminance(reference);
  const double avg = toneMap.averageRadiance;
  double sqTone = 0, sqDiff = 0, sqRef = 0, sumTest[3] = {0, 0, 0}, sumRef[3] = {0, 0, 0};
  double sumAB[3] = {0, 0, 0}, sumAA[3] = {0, 0, 0};
  for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
    const glm::vec4 &a = test.pixels[i], &b = reference.pixels[i];
    const bool ca = test.covered(i), cb = reference.covered(i);
    if (ca != cb) ++e.coverageMismatch;
    for (int c = 0; c < 3; ++c) {
      const double ta = toneMap.apply(a[c], avg), tb = toneMap.apply(b[c], avg);
      sqTone += (ta - tb) * (ta - tb);
      if (ca || cb) {
        const double d = double(a[c]) - double(b[c]);
        sqDiff += d * d;
        sqRef += double(b[c]) * double(b[c]);
        sumTest[c] += double(a[c]), sumRef[c] += double(b[c]);
        sumAB[c] += double(a[c]) * double(b[c]), sumAA[c] += double(a[c]) * double(a[c]);
        e.maxAbsError = std::max(e.maxAbsError, std::abs(d));
      }
    }
    if (ca || cb) ++e.coveredPixels;
  }
  e.rmseToneMapped =
      reference.pixels.empty() ? 0 : std::sqrt(sqTone / (3.0 * double(reference.pixels.size())));
  for (int c = 0; c < 3; ++c) e.meanRatio[c] = sumRef[c] > 0 ? sumTest[c] / sumRef[c] : 0.0;
  // Each channel scaled by k_c = sum(ab) / sum(a^2), the residual summed in a second pass (the
  // closed form sum b^2 - (sum ab)^2 / sum a^2 cancels to rounding noise for a good fit).
  double k[3];
  for (int c = 0; c < 3; ++c) k[c] = sumAA[c] > 0 ? sumAB[c] / sumAA[c] : 0.0;
  double residual = 0;
  for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
    if (!test.covered(i) && !reference.covered(i)) continue;
    for (int c = 0; c < 3; ++c) {
      const double d = k[c] * double(test.pixels[i][c]) - double(reference.pixels[i][c]);
      residual += d * d;
    }
  }
  e.scaledRelativeRms = sqRef > 0 ? std::sqrt(residual / sqRef) : 0.0;
  e.relativeRms = sqRef > 0 ? std::sqrt(sqDiff / sqRef)
                            : (sqDiff > 0 ? std::numeric_limits<double>::infinity() : 0.0);
  return e;
}

}  // namespace lucent::image
