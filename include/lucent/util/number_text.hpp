#pragma once
/// @file number_text.hpp
/// @brief Numbers in messages, one way everywhere: std::to_string prints %f (1e-7 reads "0.000000",
/// 1e20 twenty digits), so measured values, user values and counts each have one format here.
#include <cmath>
#include <cstdio>
#include <string>

namespace lucent::util {

/// A measured value (a residual, a ratio, a length): 3 significant digits.
inline std::string numberText(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

/// A value the user gave or must give back (a threshold, a range's ends): 6 significant digits.
inline std::string valueText(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

/// A count or a size from a file: whole numbers in full below 1e15, anything else as valueText.
inline std::string numberShown(double v) {
  char b[40];
  std::snprintf(b, sizeof b, std::fabs(v) < 1e15 && v == std::floor(v) ? "%.0f" : "%.6g", v);
  return b;
}

}  // namespace lucent::util
