#pragma once
/// @file rgb.hpp
/// @brief Three-channel (R,G,B) quantities: coefficients, radiance. A GLM vector, so arithmetic is free.
#include <glm/vec3.hpp>

namespace lucent::optics {

template <class T>
using Rgb = glm::vec<3, T, glm::defaultp>;

inline constexpr int kChannels = 3;

}  // namespace lucent::optics
