#pragma once
/// @file shepard_weights.hpp
/// @brief Inverse-square-distance (Shepard) interpolation from scattered source points: Eq. 10 of
/// Wang et al. 2010 (QuadGraph's level transfers, w = |x - y|^-2 over the b nearest sources), also
/// how a decimated graph surface or a subset of PRT transport points reaches every input vertex.
#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "nearest_points.hpp"
#include "parallel.hpp"

namespace lucent::util {

/// For each target point, `b` source indices and normalised weights (unused slots weigh 0).
struct ShepardWeights {
  std::size_t b = 0;
  std::vector<std::uint32_t> index;
  std::vector<double> weight;

  template <class T>
  void apply(const T* source, T* target, std::size_t targetCount) const {
    for (std::size_t t = 0; t < targetCount; ++t) {
      double v = 0;
      for (std::size_t k = 0; k < b; ++k) v += weight[t * b + k] * double(source[index[t * b + k]]);
      target[t] = T(v);
    }
  }

  /// The weighted sum for one target, for values that are not scalars (colours, vectors).
  template <class V>
  V at(const std::vector<V>& source, std::size_t t) const {
    V v(0);
    for (std::size_t k = 0; k < b; ++k) v += weight[t * b + k] * source[index[t * b + k]];
    return v;
  }
};

namespace detail {
/// Fills target t's slots from `near` (nearest first, squared distances), the first `kept` of them.
/// A target that coincides with its nearest source takes that source's value.
inline void fillShepardSlots(ShepardWeights& w, std::size_t t,
                             const std::vector<std::pair<std::uint32_t, double>>& near,
                             std::size_t kept) {
  const bool exact = near.front().second <= 1e-24;
  double sum = 0;
  for (std::size_t k = 0; k < kept; ++k) {
    const double wk = exact ? (k == 0 ? 1.0 : 0.0) : 1.0 / near[k].second;
    w.index[t * w.b + k] = near[k].first, w.weight[t * w.b + k] = wk, sum += wk;
  }
  for (std::size_t k = 0; k < kept; ++k) w.weight[t * w.b + k] /= sum;
  // Unused slots weigh 0 on the nearest source, so a non-finite value elsewhere cannot reach t.
  for (std::size_t k = kept; k < w.b; ++k) w.index[t * w.b + k] = near[0].first;
}
}  // namespace detail

/// Eq. 10 over the b nearest sources.
inline ShepardWeights shepardWeights(const std::vector<glm::dvec3>& sources,
                                     const std::vector<glm::dvec3>& targets, std::size_t b) {
  ShepardWeights w;
  w.b = std::min(b, sources.size());
  w.index.assign(targets.size() * w.b, 0);
  w.weight.assign(targets.size() * w.b, 0.0);
  if (w.b == 0) return w;
  const NearestPoints grid(sources);
  for (std::size_t t = 0; t < targets.size(); ++t)
    detail::fillShepardSlots(w, t, grid.nearest(targets[t], w.b), w.b);
  return w;
}

/// Eq. 10 over the up to `b` nearest sources that face the way the target's normal does (among its
/// 8 nearest): across a part thinner than the sources' spacing, the nearest source can be the other
/// side's, which the light did not reach. The plain nearest b where none faces alike.
inline ShepardWeights facingShepardWeights(const NearestPoints& sources,
                                           const std::vector<glm::dvec3>& sourceNormals,
                                           const std::vector<glm::dvec3>& targets,
                                           const std::vector<glm::dvec3>& targetNormals,
                                           std::size_t b, const ParallelFor& parallelFor) {
  constexpr std::size_t kCandidates = 8;
  ShepardWeights w;
  w.b = std::min(b, sourceNormals.size());
  w.index.assign(targets.size() * w.b, 0);
  w.weight.assign(targets.size() * w.b, 0.0);
  if (w.b == 0) return w;
  parallelFor(targets.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t) {
      auto near = sources.nearest(targets[t], kCandidates);
      const auto facing = std::stable_partition(near.begin(), near.end(), [&](const auto& c) {
        return glm::dot(sourceNormals[c.first], targetNormals[t]) > 0;
      });
      const auto facingCount = std::size_t(facing - near.begin());
      detail::fillShepardSlots(w, t, near,
                               std::min(w.b, facingCount == 0 ? near.size() : facingCount));
    }
  });
  return w;
}

}  // namespace lucent::util
