#pragma once
/// @file tonemap.hpp
/// @brief Tone mapping of linear radiance to display values in [0, 1].
///
/// The operator of Chang et al. 2008 section 3 (DirectX's HDR Lighting sample):
/// s = key * L / L_avg, colour = s / (1 + s), applied per channel, with L_avg the mean luminance of the
/// covered pixels. The extracted text of the paper lost the fraction's orientation; s/(1+s) is the
/// operator that maps [0, inf) onto [0, 1). As in the paper, no display gamma is applied: these are the
/// values RMSE is reported on. The exposure operator (clamp(L * 2^stops), then sRGB) is the plain option.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "image.hpp"

namespace lucent::image {

inline float luminance(const glm::vec4& p) { return 0.2126f * p.r + 0.7152f * p.g + 0.0722f * p.b; }

/// Mean luminance over covered pixels; 0 if nothing is covered.
inline double meanCoveredLuminance(const Image& img) {
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < img.pixels.size(); ++i)
    if (img.covered(i)) {
      sum += luminance(img.pixels[i]);
      ++n;
    }
  return n ? sum / double(n) : 0.0;
}

struct ToneMap {
  enum class Kind { Paper, Exposure } kind = Kind::Paper;
  double key = 1.0;          ///< Paper: scales L / L_avg
  double averageRadiance = 0;///< Paper: L_avg; 0 means "take it from the image being mapped"
  double exposureStops = 0;  ///< Exposure: multiply by 2^stops

  float apply(float radiance, double avg) const {
    if (!(radiance > 0)) return 0.0f;  // also maps NaN to 0: never write garbage into a picture
    if (kind == Kind::Paper) {
      if (!(avg > 0)) return 0.0f;
      const double s = key * double(radiance) / avg;
      return float(s / (1.0 + s));
    }
    const double v = std::min(1.0, double(radiance) * std::exp2(exposureStops));
    return float(v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055);
  }

  /// Display values in [0,1] in RGB; A is kept.
  Image map(const Image& img) const {
    const double avg = averageRadiance > 0 ? averageRadiance : meanCoveredLuminance(img);
    Image out(img.width, img.height);
    for (std::size_t i = 0; i < img.pixels.size(); ++i) {
      const glm::vec4& p = img.pixels[i];
      out.pixels[i] = glm::vec4(apply(p.r, avg), apply(p.g, avg), apply(p.b, avg), p.a);
    }
    return out;
  }
};

}  // namespace lucent::image
