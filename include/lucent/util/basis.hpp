#pragma once
/// @file basis.hpp
/// @brief An orthonormal basis around a unit vector, branch-free and stable (Duff et al. 2017,
/// "Building an Orthonormal Basis, Revisited"): for sampling directions around a normal or a ray.
#include <cmath>

#include <glm/vec3.hpp>

namespace lucent::util {

/// t, b, n form a right-handed orthonormal basis for unit n.
inline void orthonormalBasis(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double bb = n.x * n.y * a;
  t = glm::dvec3(1.0 + sign * n.x * n.x * a, sign * bb, -sign * n.x);
  b = glm::dvec3(bb, sign + n.y * n.y * a, -n.y);
}

}  // namespace lucent::util
