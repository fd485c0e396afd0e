#pragma once
/// @file haar.hpp
/// @brief The orthonormal 2-D non-standard Haar transform of square images (a cube face), in place.
/// Each level does one 1-D step on every row, then on every column, of the current low-pass square
/// and recurses on its top-left quarter (Stollnitz, DeRose, Salesin 1995, the non-standard
/// decomposition); a step maps (a, b) to ((a + b) / sqrt 2, (a - b) / sqrt 2), so the transform is
/// orthonormal: dot products and energies are the same in both domains (Parseval), which is what
/// lets PRT relight with a dot product of wavelet coefficients (Ng, Ramamoorthi, Hanrahan 2003).
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace lucent::prt {

inline bool isPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

namespace detail {
inline constexpr double kInvSqrt2 = 0.70710678118654752440;

/// The scalar of T: T itself, or a vector type's value_type (float for glm::vec3).
template <class T, class = void>
struct ScalarOf {
  using type = T;
};
template <class T>
struct ScalarOf<T, std::void_t<typename T::value_type>> {
  using type = typename T::value_type;
};
template <class T>
constexpr auto invSqrt2 = typename ScalarOf<T>::type(kInvSqrt2);

/// One forward step on `count` values `stride` apart: averages to the first half, details to the
/// second; `scratch` holds count values.
template <class T>
void haarStep(T* values, std::size_t stride, int count, std::vector<T>& scratch) {
  const int half = count / 2;
  for (int i = 0; i < half; ++i) {
    const T a = values[std::size_t(2 * i) * stride], b = values[std::size_t(2 * i + 1) * stride];
    scratch[i] = (a + b) * invSqrt2<T>;
    scratch[half + i] = (a - b) * invSqrt2<T>;
  }
  for (int i = 0; i < count; ++i) values[std::size_t(i) * stride] = scratch[i];
}

/// The inverse of haarStep.
template <class T>
void haarUnstep(T* values, std::size_t stride, int count, std::vector<T>& scratch) {
  const int half = count / 2;
  for (int i = 0; i < half; ++i) {
    const T s = values[std::size_t(i) * stride], d = values[std::size_t(half + i) * stride];
    scratch[2 * i] = (s + d) * invSqrt2<T>;
    scratch[2 * i + 1] = (s - d) * invSqrt2<T>;
  }
  for (int i = 0; i < count; ++i) values[std::size_t(i) * stride] = scratch[i];
}
}  // namespace detail

/// The forward transform of the n x n row-major image at `image` (n a power of two); T is a scalar
/// or a vector type with + - and * by a scalar (glm::vec3 for RGB).
template <class T>
void haarForward(T* image, int n) {
  std::vector<T> scratch(std::size_t(n) > 0 ? std::size_t(n) : 1);
  for (int side = n; side > 1; side /= 2) {
    for (int row = 0; row < side; ++row)
      detail::haarStep(image + std::size_t(row) * n, 1, side, scratch);
    for (int col = 0; col < side; ++col)
      detail::haarStep(image + col, std::size_t(n), side, scratch);
  }
}

/// The inverse of haarForward: the image again, to rounding.
template <class T>
void haarInverse(T* image, int n) {
  std::vector<T> scratch(std::size_t(n) > 0 ? std::size_t(n) : 1);
  for (int side = 2; side <= n; side *= 2) {
    for (int col = 0; col < side; ++col)
      detail::haarUnstep(image + col, std::size_t(n), side, scratch);
    for (int row = 0; row < side; ++row)
      detail::haarUnstep(image + std::size_t(row) * n, 1, side, scratch);
  }
}

/// The side, in texels, of the square that coefficient (row, column) of an n x n transform is
/// non-zero on: n for the scaling coefficient (0, 0) and the coarsest details, n / 2^j for the
/// details in the band [2^j, 2^{j+1}).
inline int supportSide(int row, int column, int n) {
  int band = row > column ? row : column, side = n;
  while (band > 1) band /= 2, side /= 2;
  return side;
}

/// The transform of each face of a cube map (6 faces of size x size, stacked), in place.
template <class T>
void haarForwardCube(std::vector<T>& texels, int size) {
  const std::size_t face = std::size_t(size) * size;
  for (std::size_t f = 0; f * face < texels.size(); ++f)
    haarForward(texels.data() + f * face, size);
}

template <class T>
void haarInverseCube(std::vector<T>& texels, int size) {
  const std::size_t face = std::size_t(size) * size;
  for (std::size_t f = 0; f * face < texels.size(); ++f)
    haarInverse(texels.data() + f * face, size);
}

}  // namespace lucent::prt
