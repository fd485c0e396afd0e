#pragma once
/// @file display_encode.hpp
/// @brief Linear radiance to a display value in [0, 1]: x / (1 + x) (never clips a highlight), then the
/// sRGB transfer curve. Used by vtkLucentFilter's colour array and, as shaders/display.glsl, by the GPU
/// composite; tests/gl/test_glsl_agreement.cpp checks that the two agree.
#include <algorithm>
#include <cmath>

namespace lucent::image {

/// sRGB transfer curve (IEC 61966-2-1) of a linear value in [0, 1].
inline double srgbEncode(double linear) {
  const double v = std::clamp(linear, 0.0, 1.0);
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
}

/// Reinhard's x / (1 + x) then sRGB; NaN, negative and infinite input give 0 (never garbage on screen).
inline double displayEncode(double radiance) {
  const double v = radiance > 0 && std::isfinite(radiance) ? radiance / (1 + radiance) : 0.0;
  return srgbEncode(v);
}

}  // namespace lucent::image
