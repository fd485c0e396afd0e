// PRT's transport points (include/lucent/prt/transport_points.hpp): a budget of vertices that carry
// transport vectors, every vertex interpolating the nearest that face its way.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include <lucent/optics/constants.hpp>
#include <lucent/prt/thin_samples.hpp>
#include <lucent/prt/transport_points.hpp>
#include <lucent/util/grid_clusters.hpp>

using namespace lucent;

namespace {

/// A unit sphere's vertices on an n x 2n latitude-longitude grid, their normals outward.
void sphere(int n, double radius, std::vector<glm::dvec3>& positions,
            std::vector<glm::dvec3>& normals) {
  for (int i = 1; i < n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      const double theta = optics::kPi * i / n, phi = optics::kPi * j / n;
      const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::cos(theta),
                         std::sin(theta) * std::sin(phi));
      positions.push_back(radius * d), normals.push_back(d);
    }
}

double weightSum(const util::ShepardWeights& w, std::size_t v) {
  double sum = 0;
  for (std::size_t k = 0; k < w.b; ++k) sum += w.weight[v * w.b + k];
  return sum;
}

}  // namespace

TEST_CASE(
    "Transport points: within the budget, spread over the surface, and a linear field interpolated "
    "closely") {
  std::vector<glm::dvec3> positions, normals;
  sphere(100, 10.0, positions, normals);  // 19800 vertices
  const prt::TransportPoints points =
      prt::chooseTransportPoints(positions, normals, 2000, 5.0, util::serialFor);
  REQUIRE_FALSE(points.everyVertex());
  CHECK_FALSE(points.spacingLimited);
  CHECK(points.vertex.size() <= 2000);
  CHECK(points.vertex.size() >= 1000);  // the bisection lands near the budget
  double farthest = 0;                  // every vertex has a point within a cell's diagonal
  for (std::size_t v = 0; v < positions.size(); ++v) {
    CHECK(weightSum(points.toVertices, v) == doctest::Approx(1.0));
    double nearest = 1e300;
    for (std::uint32_t p : points.vertex)
      nearest = std::min(nearest, glm::distance(positions[p], positions[v]));
    farthest = std::max(farthest, nearest);
  }
  CHECK(farthest <= points.cell * std::sqrt(3.0));
  // Shepard interpolation of f(p) = x + 2y - z, its error within the points' spacing's share.
  prt::VertexShading atPoints;
  for (std::uint32_t p : points.vertex) {
    const double f = positions[p].x + 2 * positions[p].y - positions[p].z;
    atPoints.diffuse.push_back(glm::dvec3(f));
  }
  const prt::VertexShading onVertices = prt::shadingOnVertices(points, atPoints);
  REQUIRE(onVertices.diffuse.size() == positions.size());
  double worst = 0;
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const double f = positions[v].x + 2 * positions[v].y - positions[v].z;
    worst = std::max(worst, std::abs(onVertices.diffuse[v].x - f));
  }
  CHECK(worst <= std::sqrt(6.0) * points.cell);  // |grad f| = sqrt(6), the nearest within a cell
}

TEST_CASE(
    "Transport points: a sheet thinner than a cell keeps a point on each side, and each side "
    "interpolates its own") {
  std::vector<glm::dvec3> positions, normals;
  for (int side = 0; side < 2; ++side)
    for (int i = 0; i < 60; ++i)
      for (int j = 0; j < 60; ++j) {
        positions.push_back({0.1 * i, 0.1 * j, side * 0.01});
        normals.push_back({0, 0, side == 0 ? -1 : 1});
      }
  const prt::TransportPoints points =
      prt::chooseTransportPoints(positions, normals, 400, 10.0, util::serialFor);
  REQUIRE_FALSE(points.everyVertex());
  std::size_t top = 0;
  for (std::uint32_t p : points.vertex) top += normals[p].z > 0;
  CHECK(top * 2 == points.vertex.size());  // one per cell and side
  const util::ShepardWeights& w = points.toVertices;
  for (std::size_t v = 0; v < positions.size(); ++v)
    for (std::size_t k = 0; k < w.b; ++k)
      if (w.weight[v * w.b + k] > 0)
        CHECK(glm::dot(normals[points.vertex[w.index[v * w.b + k]]], normals[v]) > 0);
}

TEST_CASE(
    "Transport points: every vertex when the budget is 0 or not below the count, and never sparser "
    "than the bound") {
  std::vector<glm::dvec3> positions, normals;
  sphere(40, 10.0, positions, normals);
  CHECK(prt::chooseTransportPoints(positions, normals, 0, 5.0, util::serialFor).everyVertex());
  CHECK(prt::chooseTransportPoints(positions, normals, positions.size(), 5.0, util::serialFor)
            .everyVertex());
  const prt::TransportPoints bounded =
      prt::chooseTransportPoints(positions, normals, 10, 1.0, util::serialFor);
  CHECK(bounded.spacingLimited);
  CHECK(bounded.cell == 1.0);
  CHECK(bounded.vertex.size() > 10);
}

TEST_CASE(
    "Thinned samples: one per cell and facing, on a member's position, the area kept in total") {
  reference::SurfaceSamples dense;  // a 10 x 10 mm sheet sampled every 0.05 mm on both faces
  for (int side = 0; side < 2; ++side)
    for (int i = 0; i < 200; ++i)
      for (int j = 0; j < 200; ++j) {
        dense.position.push_back(
            {0.05 * i + 0.025, 0.05 * j + 0.025, 0.01 * side});  // off the cell faces
        dense.normal.push_back({0, 0, side == 0 ? -1 : 1});
        dense.faceNormal.push_back(dense.normal.back());
        dense.area.push_back(0.0025);
      }
  // A cell of 0.52 mm, which the 0.05 mm rows do not divide: 10 or 11 rows a cell (fewer in the
  // last), 20 cells along each side of the 9.95 mm the samples span.
  const reference::SurfaceSamples thin = prt::thinSamples(dense, 0.52);
  CHECK(thin.size() == 2 * 20 * 20);
  double area = 0;
  for (double a : thin.area) area += a;
  CHECK(area == doctest::Approx(2 * 100.0));
  for (std::size_t i = 0; i < thin.size(); ++i) {
    CHECK(thin.area[i] > 0);
    CHECK(thin.area[i] <= 11 * 11 * 0.0025 * (1 + 1e-12));
    CHECK(std::find(dense.position.begin(), dense.position.end(), thin.position[i]) !=
          dense.position.end());
  }
  // Already at the spacing: left as it is.
  CHECK(prt::thinSamples(dense, 0.05).size() == dense.size());
}

TEST_CASE(
    "Grid clusters: a fine cell on a large object keeps far points apart (more cells than 2^20 an "
    "axis)") {
  std::vector<glm::dvec3> positions, normals;
  for (int i = 0; i < 50; ++i)
    positions.push_back(glm::dvec3(2.0 * i, 3.0 * i, 1.0 * i)), normals.push_back({0, 0, 1});
  const util::GridClusters c = util::gridClusters(positions, normals, 1e-5);  // 10^7 cells along x
  CHECK(c.count == positions.size());
}
