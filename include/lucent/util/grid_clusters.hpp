#pragma once
/// @file grid_clusters.hpp
/// @brief Surface points grouped by a uniform grid's cell and their normal's dominant direction (6
/// bins): a thin part's two sides in one cell stay apart. How PRT thins a dense scanned mesh's
/// vertices and triangle samples to the spacing the light transport needs.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "fingerprint.hpp"

namespace lucent::util {

struct GridClusters {
  std::vector<std::uint32_t> of;  ///< each point's cluster
  std::size_t count = 0;

  /// Each cluster's member nearest its `weight`-weighted mean position (weights empty: equal).
  std::vector<std::uint32_t> representatives(const std::vector<glm::dvec3>& positions,
                                             const std::vector<double>& weight = {}) const {
    std::vector<glm::dvec3> sum(count, glm::dvec3(0));
    std::vector<double> total(count, 0.0);
    for (std::size_t i = 0; i < of.size(); ++i) {
      const double w = weight.empty() ? 1.0 : weight[i];
      sum[of[i]] += w * positions[i], total[of[i]] += w;
    }
    std::vector<std::uint32_t> best(count, std::numeric_limits<std::uint32_t>::max());
    std::vector<double> bestDistance(count, std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < of.size(); ++i) {
      const std::uint32_t c = of[i];
      const glm::dvec3 d = positions[i] - (total[c] > 0 ? sum[c] / total[c] : positions[i]);
      if (glm::dot(d, d) < bestDistance[c] || best[c] == std::numeric_limits<std::uint32_t>::max())
        bestDistance[c] = glm::dot(d, d), best[c] = std::uint32_t(i);
    }
    return best;
  }
};

namespace detail {
/// A point's cluster: its grid cell (unbounded: a fine cell on a large object has more cells along
/// an axis than a packed key could hold) and its normal's bin.
struct GridKey {
  std::int64_t x, y, z;
  int bin;
  bool operator==(const GridKey& o) const {
    return x == o.x && y == o.y && z == o.z && bin == o.bin;
  }
};
struct GridKeyHash {
  std::size_t operator()(const GridKey& k) const {
    return std::size_t(
        Fingerprint().addValue(k.x).addValue(k.y).addValue(k.z).addValue(k.bin).value());
  }
};
}  // namespace detail

/// Clusters numbered in order of their first point.
inline GridClusters gridClusters(const std::vector<glm::dvec3>& positions,
                                 const std::vector<glm::dvec3>& normals, double cell) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity());
  for (const auto& p : positions) lo = glm::min(lo, p);
  auto keyOf = [&](std::size_t i) {
    const glm::dvec3 a = glm::abs(normals[i]);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    // Beyond 2^52 cells along an axis the cell is below rounding anyway: clamped there.
    const glm::dvec3 c = glm::min(glm::floor((positions[i] - lo) / cell), glm::dvec3(4.5e15));
    return detail::GridKey{std::int64_t(c.x), std::int64_t(c.y), std::int64_t(c.z),
                           2 * axis + (normals[i][axis] < 0 ? 1 : 0)};
  };
  GridClusters out;
  out.of.resize(positions.size());
  std::unordered_map<detail::GridKey, std::uint32_t, detail::GridKeyHash> clusterOf;
  clusterOf.reserve(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i)
    out.of[i] = clusterOf.emplace(keyOf(i), std::uint32_t(clusterOf.size())).first->second;
  out.count = clusterOf.size();
  return out;
}

}  // namespace lucent::util
