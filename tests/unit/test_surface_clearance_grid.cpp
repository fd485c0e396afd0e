// The clearance grid (scene/surface_clearance_grid.hpp) against the exact distance to every
// triangle: its bound never exceeds the distance, and deep inside it is most of it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <lucent/scene/shapes.hpp>
#include <lucent/scene/surface_clearance_grid.hpp>

using namespace lucent;

namespace {

double segmentDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double s = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + s * ab));
}

/// The distance from p to a triangle: to its plane where p projects inside it, else to the
/// nearest edge.
double triangleDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                        const glm::dvec3& c) {
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double len = glm::length(n);
  if (len > 0) {
    const glm::dvec3 u = n / len;
    const glm::dvec3 q = p - glm::dot(p - a, u) * u;
    const bool inside = glm::dot(glm::cross(b - a, q - a), n) >= 0 &&
                        glm::dot(glm::cross(c - b, q - b), n) >= 0 &&
                        glm::dot(glm::cross(a - c, q - c), n) >= 0;
    if (inside) return std::abs(glm::dot(p - a, u));
  }
  return std::min(segmentDistance(p, a, b),
                  std::min(segmentDistance(p, b, c), segmentDistance(p, c, a)));
}

double meshDistance(const scene::TriangleMesh& mesh, const glm::dvec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const glm::uvec3& t : mesh.triangles)
    best = std::min(
        best, triangleDistance(p, glm::dvec3(mesh.positions[t.x]), glm::dvec3(mesh.positions[t.y]),
                               glm::dvec3(mesh.positions[t.z])));
  return best;
}

}  // namespace

TEST_CASE("The clearance grid's bound never exceeds the distance to the surface") {
  scene::TriangleMesh degenerate = scene::shapes::sphere(1.0, 2);
  degenerate.triangles.push_back({0, 0, 1});  // a sliver with no area
  degenerate.triangles.push_back({2, 3, 2});
  const std::pair<const char*, scene::TriangleMesh> meshes[] = {
      {"sphere", scene::shapes::sphere(1.0, 3)},
      {"torus", scene::shapes::torus(1.0, 0.4, 32, 16)},
      {"box with large faces", scene::shapes::box(glm::dvec3(1.0, 0.3, 0.6), 2.0)},
      {"twirl", scene::shapes::twirl()},
      {"degenerate triangles", degenerate}};
  std::mt19937 rng(3);
  for (const auto& named : meshes) {  // no structured binding: clang 14 cannot capture one (INFO)
    const auto& name = named.first;
    const auto& mesh = named.second;
    INFO(name);
    for (int cells : {7, 64}) {
      const scene::SurfaceClearanceGrid grid(mesh, cells);
      const scene::Bounds b = mesh.bounds();
      std::uniform_real_distribution<double> x(b.lo.x - 0.2, b.hi.x + 0.2),
          y(b.lo.y - 0.2, b.hi.y + 0.2), z(b.lo.z - 0.2, b.hi.z + 0.2);
      int positive = 0;
      for (int i = 0; i < 400; ++i) {
        const glm::dvec3 p(x(rng), y(rng), z(rng));
        const double bound = grid.lowerBound(p), exact = meshDistance(mesh, p);
        CHECK(bound >= 0);
        CHECK(bound <= exact);
        positive += bound > 0;
      }
      if (cells == 64) CHECK(positive > 40);  // it is of use, not only safe
    }
  }
}

TEST_CASE("Deep inside a sphere the clearance bound is most of the distance, and outside it is 0") {
  const scene::TriangleMesh mesh = scene::shapes::sphere(1.0, 4);
  const scene::SurfaceClearanceGrid grid(mesh, 128);
  const double h = grid.cellSize();
  for (double r : {0.0, 0.3, 0.6, 0.9}) {
    const glm::dvec3 p(r / std::sqrt(3.0), r / std::sqrt(3.0), r / std::sqrt(3.0));
    const double exact = meshDistance(mesh, p);
    INFO("r " << r << ": bound " << grid.lowerBound(p) << ", distance " << exact);
    CHECK(grid.lowerBound(p) <= exact);
    // Two cells for the marked band, up to one more for the Chebyshev metric's corners.
    CHECK(grid.lowerBound(p) >= exact / std::sqrt(3.0) - 3 * h);
  }
  CHECK(grid.lowerBound(glm::dvec3(5, 0, 0)) == 0);
  CHECK(grid.lowerBound(glm::dvec3(std::nan(""))) == 0);
  CHECK(scene::SurfaceClearanceGrid().lowerBound(glm::dvec3(0)) == 0);
}
