#pragma once
/// @file cube_map.hpp
/// @brief The geometry of a cube map of 6 x N x N texels: faces in OpenGL's order and orientation
/// (+x, -x, +y, -y, +z, -z; a face's column grows with s, its row with t, as glTexImage2D's faces),
/// the direction through a face point, the texel a direction falls in, and each texel's exact solid
/// angle, int dA / (1 + s^2 + t^2)^{3/2} over the texel, which sums to 4 pi.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace lucent::scene::cube {

inline constexpr int kFaces = 6;

/// The unnormalised direction through face point (s, t) in [-1, 1]^2 (OpenGL's table 8.19,
/// inverted).
inline glm::dvec3 faceDirection(int face, double s, double t) {
  switch (face) {
    case 0:
      return {1, -t, -s};
    case 1:
      return {-1, -t, s};
    case 2:
      return {s, 1, t};
    case 3:
      return {s, -1, -t};
    case 4:
      return {s, -t, 1};
    default:
      return {-s, -t, -1};
  }
}

/// A direction's face and its face coordinates (s, t) in [-1, 1]^2; the inverse of faceDirection.
struct FacePoint {
  int face = 0;
  double s = 0, t = 0;
};

inline FacePoint facePoint(const glm::dvec3& d) {
  const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
  if (ax >= ay && ax >= az) {
    if (!(ax > 0)) return {};  // the zero vector (or NaN): face 0's centre, never out of range
    return d.x > 0 ? FacePoint{0, -d.z / ax, -d.y / ax} : FacePoint{1, d.z / ax, -d.y / ax};
  }
  if (ay >= az)
    return d.y > 0 ? FacePoint{2, d.x / ay, d.z / ay} : FacePoint{3, d.x / ay, -d.z / ay};
  return d.z > 0 ? FacePoint{4, d.x / az, -d.y / az} : FacePoint{5, -d.x / az, -d.y / az};
}

/// The face coordinate of texel edge `i` of `size` (0 and size are the face's sides).
inline double edgeCoordinate(int i, int size) { return 2.0 * i / size - 1; }

/// The texel index face * size^2 + row * size + column that direction `d` falls in.
inline std::size_t texelIndex(const glm::dvec3& d, int size) {
  const FacePoint p = facePoint(d);
  auto cell = [size](double c) { return std::clamp(int((c + 1) * 0.5 * size), 0, size - 1); };
  return (std::size_t(p.face) * size + cell(p.t)) * std::size_t(size) + cell(p.s);
}

/// The solid angle of face rectangle [0, x] x [0, y]: atan(x y / sqrt(1 + x^2 + y^2)).
inline double cornerSolidAngle(double x, double y) {
  return std::atan2(x * y, std::sqrt(1 + x * x + y * y));
}

/// The exact solid angle of face rectangle [s0, s1] x [t0, t1].
inline double rectangleSolidAngle(double s0, double s1, double t0, double t1) {
  return cornerSolidAngle(s1, t1) - cornerSolidAngle(s0, t1) - cornerSolidAngle(s1, t0) +
         cornerSolidAngle(s0, t0);
}

/// The exact solid angle of texel (row, column) of a face `size` texels across (the same on all
/// faces).
inline double texelSolidAngle(int row, int column, int size) {
  return rectangleSolidAngle(edgeCoordinate(column, size), edgeCoordinate(column + 1, size),
                             edgeCoordinate(row, size), edgeCoordinate(row + 1, size));
}

/// The unit direction through the centre of texel `index` (face * size^2 + row * size + column).
inline glm::dvec3 texelCentre(std::size_t index, int size) {
  const std::size_t n = std::size_t(size);
  const int face = int(index / (n * n)), row = int(index / n % n), column = int(index % n);
  return glm::normalize(
      faceDirection(face, (column + 0.5) * 2.0 / size - 1, (row + 0.5) * 2.0 / size - 1));
}

}  // namespace lucent::scene::cube
