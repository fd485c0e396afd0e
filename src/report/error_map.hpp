#pragma once
/// @file error_map.hpp
/// @brief A picture of where an image differs from its reference: per pixel |L - L_ref| over the
/// reference's mean luminance, in a perceptually ordered ramp (black, purple, orange, yellow).
#include <lucent/image/image.hpp>

namespace lucent::report {

/// Display values of the relative error map; `fullScale` is the error shown as the ramp's top
/// (yellow). Pixels covered by neither image are white; by one only, full scale.
image::Image relativeErrorMap(const image::Image& test, const image::Image& reference,
                              double fullScale);

}  // namespace lucent::report
