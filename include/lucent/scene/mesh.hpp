#pragma once
/// @file mesh.hpp
/// @brief An indexed triangle mesh in millimetres, with the geometric helpers every technique needs.
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace lucent::scene {

struct Bounds {
  glm::dvec3 lo{std::numeric_limits<double>::infinity()};
  glm::dvec3 hi{-std::numeric_limits<double>::infinity()};
  void extend(const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  glm::dvec3 center() const { return 0.5 * (lo + hi); }
  double diagonal() const { return glm::length(hi - lo); }
};

struct TriangleMesh {
  std::vector<glm::vec3> positions;   ///< mm
  std::vector<glm::uvec3> triangles;  ///< counter-clockwise seen from outside

  Bounds bounds() const {
    Bounds b;
    for (const auto& p : positions) b.extend(glm::dvec3(p));
    return b;
  }

  /// Twice the area vector of triangle t (its direction is the outward normal for a CCW triangle).
  glm::dvec3 areaVector(std::size_t t) const {
    const glm::dvec3 a(positions[triangles[t].x]), b(positions[triangles[t].y]), c(positions[triangles[t].z]);
    return glm::cross(b - a, c - a);
  }
  double triangleArea(std::size_t t) const { return 0.5 * glm::length(areaVector(t)); }

  double surfaceArea() const {
    double sum = 0;
    for (std::size_t t = 0; t < triangles.size(); ++t) sum += triangleArea(t);
    return sum;
  }

  /// Signed enclosed volume (divergence theorem): positive when the faces point outward.
  double signedVolume() const {
    double sum = 0;
    for (const auto& tri : triangles)
      sum += glm::dot(glm::dvec3(positions[tri.x]), glm::cross(glm::dvec3(positions[tri.y]), glm::dvec3(positions[tri.z])));
    return sum / 6.0;
  }

  /// Area-weighted vertex normals: smooth shading normals for curved surfaces tessellated coarsely.
  std::vector<glm::vec3> vertexNormals() const {
    std::vector<glm::dvec3> acc(positions.size(), glm::dvec3(0));
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      const glm::dvec3 n = areaVector(t);
      for (int k = 0; k < 3; ++k) acc[triangles[t][k]] += n;
    }
    std::vector<glm::vec3> normals(positions.size());
    for (std::size_t i = 0; i < acc.size(); ++i) {
      const double len = glm::length(acc[i]);
      normals[i] = len > 0 ? glm::vec3(acc[i] / len) : glm::vec3(0, 0, 1);
    }
    return normals;
  }

  /// Centres the mesh on the origin and scales it so that its bounding-box diagonal is sizeMm.
  /// Returns the scale factor applied.
  double scaleToSize(double sizeMm) {
    const Bounds b = bounds();
    const double diag = b.diagonal();
    if (!(diag > 0) || !(sizeMm > 0)) return 1.0;
    const double s = sizeMm / diag;
    const glm::dvec3 c = b.center();
    for (auto& p : positions) p = glm::vec3((glm::dvec3(p) - c) * s);
    return s;
  }
};

/// The smooth shading normal at barycentrics (w0, w1, w2) of triangle t: the interpolated vertex normal,
/// or the face normal where the interpolation vanishes (opposite normals at a crease).
inline glm::dvec3 shadingNormal(const TriangleMesh& mesh, const std::vector<glm::vec3>& vertexNormals, std::size_t t,
                                const glm::dvec3& w) {
  const auto& tri = mesh.triangles[t];
  const glm::dvec3 n = w.x * glm::dvec3(vertexNormals[tri.x]) + w.y * glm::dvec3(vertexNormals[tri.y]) +
                       w.z * glm::dvec3(vertexNormals[tri.z]);
  const double len = glm::length(n);
  return len > 0 ? n / len : glm::normalize(mesh.areaVector(t));
}

}  // namespace lucent::scene
