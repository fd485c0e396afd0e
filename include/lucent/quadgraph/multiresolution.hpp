#pragma once
/// @file multiresolution.hpp
/// @brief The multi-resolution scheme of Wang et al. 2010 Sec. 4.3: levels built independently from
/// simplified surfaces; the coarsest is solved first and each solution, resampled with precomputed
/// Shepard weights (Eq. 10: w = |x - y|^-2, normalised, from the b nearest coarse nodes of the same kind,
/// b = 4 for surface nodes and 8 for inner nodes), starts the next level's iterations.
#include <cstdint>
#include <vector>

#include "../util/shepard_weights.hpp"
#include "solvers.hpp"

namespace lucent::quadgraph {

/// Resampling from a coarse level to the next finer one, inner and surface nodes kept apart.
struct LevelTransfer {
  util::ShepardWeights inner, surface;
};

inline LevelTransfer levelTransfer(const QuadGraph& coarse, const QuadGraph& fine, std::size_t bSurface = 4,
                                   std::size_t bInner = 8) {
  auto slice = [](const QuadGraph& g, bool surface) {
    return std::vector<glm::dvec3>(g.positions.begin() + (surface ? std::ptrdiff_t(g.innerCount()) : 0),
                                   surface ? g.positions.end() : g.positions.begin() + std::ptrdiff_t(g.innerCount()));
  };
  LevelTransfer t;
  t.inner = util::shepardWeights(slice(coarse, false), slice(fine, false), bInner);
  t.surface = util::shepardWeights(slice(coarse, true), slice(fine, true), bSurface);
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
