#include <doctest/doctest.h>

#include <random>

#include <lucent/technique/pareto.hpp>

namespace lt = lucent::technique;

namespace {
/// The definition, pair by pair: i is on the front when no j dominates it (and, of exact ties, no
/// earlier j equals it).
bool dominated(const std::vector<lt::CostPoint>& p, std::size_t i) {
  for (std::size_t j = 0; j < p.size(); ++j) {
    if (j == i) continue;
    const bool noWorse = p[j].seconds <= p[i].seconds && p[j].error <= p[i].error;
    const bool better = p[j].seconds < p[i].seconds || p[j].error < p[i].error;
    if (noWorse && (better || j < i)) return true;
  }
  return false;
}
}  // namespace

TEST_CASE("Pareto front: equals the pairwise definition on random point sets with ties") {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(0, 12);  // a coarse grid, so that ties occur
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<lt::CostPoint> p(std::size_t(1 + trial % 30));
    for (auto& q : p) q = {double(coord(rng)), double(coord(rng))};
    const auto front = lt::paretoFront(p);
    std::vector<bool> on(p.size(), false);
    for (std::size_t k = 0; k < front.size(); ++k) {
      on[front[k]] = true;
      if (k > 0) {  // by increasing time and decreasing error
        CHECK(p[front[k]].seconds > p[front[k - 1]].seconds);
        CHECK(p[front[k]].error < p[front[k - 1]].error);
      }
    }
    for (std::size_t i = 0; i < p.size(); ++i) CHECK(on[i] == !dominated(p, i));
  }
}

TEST_CASE("Pareto front: non-finite and negative points are left out, an empty set has none") {
  CHECK(lt::paretoFront({}).empty());
  const std::vector<lt::CostPoint> p{{1, std::nan("")}, {INFINITY, 0.1}, {-1, 0.2}, {2, 0.5}};
  const auto front = lt::paretoFront(p);
  REQUIRE(front.size() == 1);
  CHECK(front[0] == 3);
}
