#pragma once
/// @file cube_layouts.hpp
/// @brief The image layouts a cube-map environment is read from, and where each face's texel lies
/// in them. Faces keep OpenGL's orientation (cube_map.hpp) except the vertical cross's -z, turned
/// by 180 degrees so that its edges meet -y's; in both crosses neighbouring faces share their
/// edges.
///   horizontal strip 6N x N:  +x -x +y -y +z -z left to right
///   vertical strip   N x 6N:  the same, top to bottom
///   horizontal cross 4N x 3N: +y above +z; -x +z +x -z in the middle row; -y below +z
///   vertical cross   3N x 4N: +y; -x +z +x; -y; -z (turned) in the middle column
#include <array>
#include <optional>
#include <string>

namespace lucent::scene::cube {

enum class ImageLayout { HorizontalStrip, VerticalStrip, HorizontalCross, VerticalCross };

inline const char* layoutName(ImageLayout l) {
  switch (l) {
    case ImageLayout::HorizontalStrip:
      return "horizontal strip (6N x N)";
    case ImageLayout::VerticalStrip:
      return "vertical strip (N x 6N)";
    case ImageLayout::HorizontalCross:
      return "horizontal cross (4N x 3N)";
    default:
      return "vertical cross (3N x 4N)";
  }
}

/// The cube layout of a width x height image, or none when its shape matches none of them.
inline std::optional<ImageLayout> detectLayout(int width, int height) {
  if (width <= 0 || height <= 0) return std::nullopt;
  if (width == 6 * height) return ImageLayout::HorizontalStrip;
  if (height == 6 * width) return ImageLayout::VerticalStrip;
  if (width % 4 == 0 && 3 * width == 4 * height) return ImageLayout::HorizontalCross;
  if (height % 4 == 0 && 4 * width == 3 * height) return ImageLayout::VerticalCross;
  return std::nullopt;
}

/// Texels across a face of an image in `layout`.
inline int faceSize(ImageLayout layout, int width, int height) {
  switch (layout) {
    case ImageLayout::HorizontalStrip:
      return height;
    case ImageLayout::VerticalStrip:
      return width;
    case ImageLayout::HorizontalCross:
      return width / 4;
    default:
      return width / 3;
  }
}

/// The image pixel (x, y) holding texel (row, column) of `face`, in an image of faces `size`
/// across.
inline std::array<int, 2> imagePixel(ImageLayout layout, int size, int face, int row, int column) {
  // The cell (in faces) of each face, +x -x +y -y +z -z.
  static constexpr int kHorizontalCross[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}};
  static constexpr int kVerticalCross[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {1, 3}};
  switch (layout) {
    case ImageLayout::HorizontalStrip:
      return {face * size + column, row};
    case ImageLayout::VerticalStrip:
      return {column, face * size + row};
    case ImageLayout::HorizontalCross:
      return {kHorizontalCross[face][0] * size + column, kHorizontalCross[face][1] * size + row};
    default:
      if (face == 5) row = size - 1 - row, column = size - 1 - column;  // -z turned by 180 degrees
      return {kVerticalCross[face][0] * size + column, kVerticalCross[face][1] * size + row};
  }
}

}  // namespace lucent::scene::cube
