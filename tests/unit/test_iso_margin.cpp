// keepOffThreshold: every crossing of the threshold along a grid edge lies at least the margin away
// from both ends, no offset is zero, and no node changes side (scene/iso_margin.hpp).
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include <lucent/scene/iso_margin.hpp>

namespace {
/// The least fraction of an edge between a crossing and its nearer end over every crossed edge.
double closestCrossing(const std::vector<float>& d, const glm::ivec3& dims) {
  double least = 1;
  std::size_t nb[6];
  for (std::size_t n = 0; n < d.size(); ++n) {
    const int count = lucent::scene::detail::gridNeighbours(dims, n, nb);
    for (int c = 0; c < count; ++c)
      if ((d[n] > 0) != (d[nb[c]] > 0)) {
        const double a = std::fabs(double(d[n])), b = std::fabs(double(d[nb[c]]));
        least = std::min(least, a / (a + b));
      }
  }
  return least;
}
}  // namespace

TEST_CASE("integer scan values at an integer threshold: every crossing leaves the grid nodes") {
  const glm::ivec3 dims(17, 13, 11);
  std::mt19937 rng(7);
  // A scan's integers, most of them within a few steps of the threshold 50, some far off.
  std::uniform_int_distribution<int> near(47, 53), far(0, 30000);
  std::vector<float> d(std::size_t(dims.x * dims.y * dims.z));
  for (auto& v : d) v = float((rng() % 8 == 0 ? far(rng) : near(rng)) - 50);
  const std::vector<float> before = d;
  CHECK(closestCrossing(before, dims) == 0.0);  // values at the threshold: crossings on the nodes

  lucent::scene::keepOffThreshold(d, dims);
  for (std::size_t n = 0; n < d.size(); ++n) {
    CHECK(d[n] != 0.0f);
    CHECK((d[n] > 0) == (before[n] > 0));  // 0 (at the threshold) counts as outside
    CHECK(std::fabs(d[n]) >= std::fabs(before[n]));
  }
  CHECK(closestCrossing(d, dims) >= doctest::Approx(lucent::scene::kIsoVertexMargin).epsilon(1e-4));
}

TEST_CASE("offsets far from the threshold are left as they are") {
  const glm::ivec3 dims(4, 4, 4);
  std::vector<float> d(64, -10.0f);
  d[21] = 5.0f;  // one voxel inside, crossings at 1/3 of each edge
  const std::vector<float> before = d;
  lucent::scene::keepOffThreshold(d, dims);
  CHECK(d == before);
}

TEST_CASE("a flat scan at the threshold has no crossing, and a margin of zero changes nothing") {
  const glm::ivec3 dims(3, 3, 3);
  std::vector<float> flat(27, 0.0f);
  lucent::scene::keepOffThreshold(flat, dims);
  for (float v : flat) CHECK((v < 0 && v > -1e-30f));
  std::vector<float> d(27, -1.0f);
  d[13] = 1e-6f;
  lucent::scene::keepOffThreshold(d, dims, 0.0);
  CHECK(d[13] == 1e-6f);
}
