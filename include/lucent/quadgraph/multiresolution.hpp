#pragma once
/// @file multiresolution.hpp
/// @brief The multi-resolution scheme of Wang et al. 2010 Sec. 4.3: levels built independently from
/// simplified surfaces; the coarsest is solved first and each solution, resampled with precomputed
/// Shepard weights (Eq. 10: w = |x - y|^-2, normalised, from the b nearest coarse nodes of the same kind,
/// b = 4 for surface nodes and 8 for inner nodes), starts the next level's iterations.
#include <cstdint>
#include <vector>

#include "../util/nearest_points.hpp"
#include "solvers.hpp"

namespace lucent::quadgraph {

/// For each target point, `b` source indices and normalised weights.
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
};

/// Eq. 10. A target that coincides with a source takes that source's value.
inline ShepardWeights shepardWeights(const std::vector<glm::dvec3>& sources, const std::vector<glm::dvec3>& targets,
                                     std::size_t b) {
  ShepardWeights w;
  w.b = std::min(b, sources.size());
  w.index.resize(targets.size() * w.b);
  w.weight.resize(targets.size() * w.b);
  const util::NearestPoints grid(sources);
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const auto near = grid.nearest(targets[t], w.b);
    double sum = 0;
    const bool exact = near.front().second <= 1e-24;
    for (std::size_t k = 0; k < w.b; ++k) {
      const double wk = exact ? (k == 0 ? 1.0 : 0.0) : 1.0 / near[k].second;
      w.index[t * w.b + k] = near[k].first;
      w.weight[t * w.b + k] = wk;
      sum += wk;
    }
    for (std::size_t k = 0; k < w.b; ++k) w.weight[t * w.b + k] /= sum;
  }
  return w;
}

/// Resampling from a coarse level to the next finer one, inner and surface nodes kept apart.
struct LevelTransfer {
  ShepardWeights inner, surface;
};

inline LevelTransfer levelTransfer(const QuadGraph& coarse, const QuadGraph& fine, std::size_t bSurface = 4,
                                   std::size_t bInner = 8) {
  auto slice = [](const QuadGraph& g, bool surface) {
    return std::vector<glm::dvec3>(g.positions.begin() + (surface ? std::ptrdiff_t(g.innerCount()) : 0),
                                   surface ? g.positions.end() : g.positions.begin() + std::ptrdiff_t(g.innerCount()));
  };
  LevelTransfer t;
  t.inner = shepardWeights(slice(coarse, false), slice(fine, false), bInner);
  t.surface = shepardWeights(slice(coarse, true), slice(fine, true), bSurface);
  return t;
}

template <class T>
std::vector<T> prolong(const LevelTransfer& t, const DiffusionSystem<T>& coarse, const std::vector<T>& coarsePhi,
                       const DiffusionSystem<T>& fine) {
  std::vector<T> phi(fine.nodeCount);
  t.inner.apply(coarsePhi.data(), phi.data(), fine.innerCount);
  t.surface.apply(coarsePhi.data() + coarse.innerCount, phi.data() + fine.innerCount, fine.nodeCount - fine.innerCount);
  return phi;
}

/// One level's problem: its system, its SOR colouring (empty unless SOR is used) and right-hand side.
template <class T>
struct LevelProblem {
  const DiffusionSystem<T>* system = nullptr;
  Colouring colours;
  std::vector<T> rhs;
};

/// Solves coarse to fine (Fig. 9). transfers[h] maps level h to h + 1. Returns one report per level and
/// leaves the finest solution in `phi`.
template <class T>
std::vector<SolveReport> solveMultiresolution(Solver solver, const std::vector<LevelProblem<T>>& levels,
                                              const std::vector<LevelTransfer>& transfers, std::vector<T>& phi,
                                              const SolveOptions& options,
                                              const util::ParallelFor& parallelFor = util::serialFor) {
  std::vector<SolveReport> reports;
  phi.assign(levels.front().system->nodeCount, T(0));
  for (std::size_t h = 0; h < levels.size(); ++h) {
    if (h > 0) phi = prolong(transfers[h - 1], *levels[h - 1].system, phi, *levels[h].system);
    reports.push_back(solve(solver, *levels[h].system, levels[h].colours, levels[h].rhs, phi, options, parallelFor));
  }
  return reports;
}

}  // namespace lucent::quadgraph
