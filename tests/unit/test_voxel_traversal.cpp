// The exact voxel walk (grid_traversal.hpp) against independent references: dense point sampling of
// the same grid, the analytic chord of a cube with a spherical cavity, and the symmetry of tau.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include <lucent/voxel/grid_traversal.hpp>

using namespace lucent;

namespace {
/// A cube of side 2 centred at the origin, medium 1, with a spherical cavity of radius r (medium 0)
/// and an inner ball of medium 2 of radius r/2 inside the cavity's centre when `inner`; voxelised
/// by the voxel centre's inside test.
voxel::MediaGrid cubeWithCavity(int n, double r, bool inner,
                                glm::dvec3 spacingScale = glm::dvec3(1)) {
  const glm::dvec3 spacing = 2.0 / double(n) * spacingScale;
  const glm::ivec3 dims = glm::ivec3(glm::ceil(2.0 / spacing));
  voxel::MediaGrid g(dims, glm::dvec3(-1), spacing, 1);
  for (int z = 0; z < dims.z; ++z)
    for (int y = 0; y < dims.y; ++y)
      for (int x = 0; x < dims.x; ++x) {
        const glm::dvec3 c = g.centre({x, y, z});
        if (glm::any(glm::greaterThan(glm::abs(c), glm::dvec3(1))))
          g.set({x, y, z}, 0);
        else if (inner && glm::length(c) < r / 2)
          g.set({x, y, z}, 2);
        else if (glm::length(c) < r)
          g.set({x, y, z}, 0);
      }
  return g;
}

/// Lengths per medium by sampling the voxel under N midpoints along the segment: an independent
/// estimate, off by at most one sample's length per boundary crossed.
std::vector<double> sampledLengths(const voxel::MediaGrid& g, glm::dvec3 a, glm::dvec3 b, int media,
                                   int n) {
  std::vector<double> out(std::size_t(media), 0.0);
  const double step = glm::length(b - a) / n;
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 p = a + (b - a) * ((i + 0.5) / n);
    const glm::ivec3 v = g.voxelOf(p);
    if (g.contains(v)) out[g.at(v)] += step;
  }
  return out;
}
}  // namespace

TEST_CASE("Voxel walk: per-medium path lengths equal dense sampling of the same grid") {
  const voxel::MediaGrid g = cubeWithCavity(24, 0.6, true, glm::dvec3(1, 0.7, 1.3));  // anisotropic
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.3, 1.3);
  constexpr int kSamples = 400000;
  for (int i = 0; i < 50; ++i) {
    const glm::dvec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    const auto exact = voxel::pathLengths(g, a, b, 3);
    const auto sampled = sampledLengths(g, a, b, 3, kSamples);
    const double crossings = 3.0 * 40;  // at most dims.x + dims.y + dims.z boundaries
    for (int m = 0; m < 3; ++m)
      CHECK(std::abs(exact[std::size_t(m)] - sampled[std::size_t(m)]) <=
            crossings * glm::length(b - a) / kSamples + 1e-12);
    // Inside the box the lengths tile the clipped segment exactly.
    double t0 = 0, t1 = 0, sum = exact[0] + exact[1] + exact[2];
    const double inside = voxel::clipToGrid(g, a, b, t0, t1) ? (t1 - t0) * glm::length(b - a) : 0.0;
    CHECK(sum == doctest::Approx(inside).epsilon(1e-12));
  }
}

TEST_CASE(
    "Voxel walk: tau is symmetric and, for piecewise-constant media, the sum of sigma_t x length") {
  const voxel::MediaGrid g = cubeWithCavity(20, 0.5, true);
  const std::vector<double> sigmaT = {0.0, 1.7, 9.0};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.99, 0.99);
  for (int i = 0; i < 200; ++i) {
    const glm::dvec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    const double forward = voxel::opticalThickness(voxel::pathLengths(g, a, b, 3), sigmaT);
    const double backward = voxel::opticalThickness(voxel::pathLengths(g, b, a, 3), sigmaT);
    CHECK(forward == doctest::Approx(backward).epsilon(1e-12));
    // The same tau by integrating sigma_t along the segment voxel by voxel, independently.
    double integral = 0;
    voxel::traverse(g, a, b, [&](const glm::ivec3& v, double t0, double t1) {
      integral += sigmaT[g.at(v)] * (t1 - t0) * glm::length(b - a);
    });
    CHECK(forward == doctest::Approx(integral).epsilon(1e-12));
  }
}

TEST_CASE(
    "Voxel walk: the chord through a cube with a spherical cavity converges to the analytic one") {
  // The line y = 0.11, z = -0.07 along x: cube chord 2, minus the cavity's chord 2 sqrt(r^2 - h^2).
  const double r = 0.6, h2 = 0.11 * 0.11 + 0.07 * 0.07;
  const double analytic = 2.0 - 2.0 * std::sqrt(r * r - h2);
  const glm::dvec3 a(-1.5, 0.11, -0.07), b(1.5, 0.11, -0.07);
  for (int n : {16, 64, 256}) {
    const auto lengths = voxel::pathLengths(cubeWithCavity(n, r, false), a, b, 2);
    const double error = std::abs(lengths[1] - analytic);
    INFO(n << " voxels a side: medium length " << lengths[1] << ", analytic " << analytic);
    CHECK(error <= 2 * 2.0 / n);  // the cavity's two walls, each within a voxel: O(1/n)
    CHECK(lengths[0] + lengths[1] ==
          doctest::Approx(3.0 - 1.0).epsilon(1e-12));  // the box is 2 wide
  }
}

TEST_CASE("Voxel walk: hard cases give finite lengths and no out-of-range voxel") {
  const voxel::MediaGrid g = cubeWithCavity(8, 0.5, false);
  auto check = [&](glm::dvec3 a, glm::dvec3 b) {
    double sum = 0;
    voxel::traverse(g, a, b, [&](const glm::ivec3& v, double t0, double t1) {
      CHECK(g.contains(v));
      CHECK(t1 > t0);
      sum += t1 - t0;
    });
    CHECK(std::isfinite(sum));
    CHECK(sum <= 1.0 + 1e-12);
    return sum;
  };
  CHECK(check({2, 2, 2}, {3, 3, 3}) == 0);                      // misses the grid
  CHECK(check({0.1, 0.2, 0.3}, {0.1, 0.2, 0.3}) == 0);          // zero length
  CHECK(check({-1, -1, -1}, {1, 1, 1}) == doctest::Approx(1));  // corner to corner, through edges
  CHECK(check({-1.5, 0.25, 0.5}, {1.5, 0.25, 0.5}) == doctest::Approx(2.0 / 3));  // on voxel faces
  CHECK(check({0.75, 0.5, -0.25}, {-0.75, 0.5, -0.25}) == doctest::Approx(1));  // starts on a face
  const voxel::MediaGrid empty;
  bool visited = false;
  voxel::traverse(empty, {0, 0, 0}, {1, 1, 1}, [&](auto&&...) { visited = true; });
  CHECK_FALSE(visited);
  // Tiny and huge voxels: the same walk scaled.
  for (double scale : {1e-6, 1e6}) {
    voxel::MediaGrid s = g;
    s.origin *= scale, s.spacing *= scale;
    const auto lengths = voxel::pathLengths(s, glm::dvec3(-1.5, 0.11, -0.07) * scale,
                                            glm::dvec3(1.5, 0.11, -0.07) * scale, 2);
    const auto unit = voxel::pathLengths(g, {-1.5, 0.11, -0.07}, {1.5, 0.11, -0.07}, 2);
    CHECK(lengths[1] / scale == doctest::Approx(unit[1]).epsilon(1e-9));
  }
}
