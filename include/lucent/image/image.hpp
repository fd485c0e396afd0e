#pragma once
/// @file image.hpp
/// @brief A linear HDR RGBA image: RGB radiance, A = coverage (1 where the object was hit).
#include <cstddef>
#include <vector>

#include <glm/vec4.hpp>

namespace lucent::image {

struct Image {
  int width = 0, height = 0;
  std::vector<glm::vec4> pixels;  ///< row-major, row 0 on top

  Image() = default;
  Image(int w, int h) : width(w), height(h), pixels(std::size_t(w) * std::size_t(h), glm::vec4(0)) {}
  glm::vec4& at(int x, int y) { return pixels[std::size_t(y) * width + x]; }
  const glm::vec4& at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
  bool covered(std::size_t i) const { return pixels[i].a > 0.5f; }
};

}  // namespace lucent::image
