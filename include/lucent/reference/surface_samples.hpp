#pragma once
/// @file surface_samples.hpp
/// @brief Dense, deterministic surface samples for the brute-force dipole integral B(xo) = int_A E
/// Rd dA (Chang et al. 2008 Eq. 3).
///
/// Each triangle is split into n^2 congruent sub-triangles (n = ceil(longest edge / spacing)) and
/// each sub-triangle contributes its centroid with its area: the midpoint rule, second-order
/// accurate in the spacing wherever the integrand is smooth. Halving the spacing quarters the
/// error, which is what the convergence study checks.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "../scene/mesh.hpp"

namespace lucent::reference {

struct SurfaceSamples {
  std::vector<glm::dvec3> position;    ///< mm
  std::vector<glm::dvec3> normal;      ///< interpolated shading normal, unit
  std::vector<glm::dvec3> faceNormal;  ///< geometric normal of the source triangle, unit
  std::vector<double> area;            ///< mm^2
  double spacing = 0;                  ///< requested spacing (mm): no sub-triangle edge is longer

  std::size_t size() const { return position.size(); }
};

/// Number of samples buildSurfaceSamples would produce, without building them.
/// Saturates at the largest size_t rather than overflow (a spacing of 1e-9 mm asks for ~10^21).
inline std::size_t countSurfaceSamples(const scene::TriangleMesh& mesh, double spacing) {
  double total = 0;
  for (const auto& tri : mesh.triangles) {
    const glm::dvec3 a(mesh.positions[tri.x]), b(mesh.positions[tri.y]), c(mesh.positions[tri.z]);
    const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    const double n = std::max(1.0, std::ceil(longest / spacing));
    total += n * n;
  }
  const double most = double(std::numeric_limits<std::size_t>::max());
  return total >= most ? std::numeric_limits<std::size_t>::max() : std::size_t(total);
}

inline SurfaceSamples buildSurfaceSamples(const scene::TriangleMesh& mesh, double spacing) {
  SurfaceSamples s;
  s.spacing = spacing;
  const std::vector<glm::vec3> vn = mesh.vertexNormals();
  const std::size_t count = countSurfaceSamples(mesh, spacing);
  s.position.reserve(count);
  s.normal.reserve(count);
  s.faceNormal.reserve(count);
  s.area.reserve(count);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const glm::dvec3 a(mesh.positions[tri.x]), b(mesh.positions[tri.y]), c(mesh.positions[tri.z]);
    const glm::dvec3 na(vn[tri.x]), nb(vn[tri.y]), nc(vn[tri.z]);
    const glm::dvec3 areaVec = glm::cross(b - a, c - a);
    const double areaLen = glm::length(areaVec);
    if (!(areaLen > 0)) continue;  // degenerate faces carry no area
    const glm::dvec3 faceN = areaVec / areaLen;
    const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    const int n = std::max(1, int(std::ceil(longest / spacing)));
    const double subArea = 0.5 * areaLen / double(n) / double(n);
    auto emit = [&](double u, double v) {  // barycentrics of b and c
      const double w = 1.0 - u - v;
      s.position.push_back(w * a + u * b + v * c);
      const glm::dvec3 nn = w * na + u * nb + v * nc;
      const double len = glm::length(nn);
      s.normal.push_back(len > 0 ? nn / len : faceN);
      s.faceNormal.push_back(faceN);
      s.area.push_back(subArea);
    };
    const double inv3n = 1.0 / (3.0 * n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        emit((3 * i + 1) * inv3n, (3 * j + 1) * inv3n);                      // upright sub-triangle
        if (i + j <= n - 2) emit((3 * i + 2) * inv3n, (3 * j + 2) * inv3n);  // inverted neighbour
      }
  }
  return s;
}

}  // namespace lucent::reference
