#pragma once
/// @file block_packing.hpp
/// @brief Node orderings for memory locality (Wang et al. 2010 Sec. 5.1, Fig. 7): inner nodes are packed
/// in blocks of r x r by breadth-first traversal from a seed, the traversal passing through nodes already
/// assigned without taking them; surface nodes follow their inner nodes (proximity on the surface).
/// A random ordering is the paper's baseline ("random storage").
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "quad_graph.hpp"

namespace lucent::quadgraph {

/// Reorders the nodes: innerOrder[new] = old inner index, surfaceOrder[new] = old surface index.
inline void permuteNodes(QuadGraph& g, const std::vector<std::uint32_t>& innerOrder,
                         const std::vector<std::uint32_t>& surfaceOrder) {
  const std::size_t ni = g.innerCount(), ns = g.surfaceCount();
  std::vector<std::uint32_t> newIndex(ni + ns);  // old node -> new node
  for (std::size_t n = 0; n < ni; ++n) newIndex[innerOrder[n]] = std::uint32_t(n);
  for (std::size_t n = 0; n < ns; ++n) newIndex[ni + surfaceOrder[n]] = std::uint32_t(ni + n);
  QuadGraph out = g;
  for (std::size_t n = 0; n < ni; ++n) {
    const std::uint32_t old = innerOrder[n];
    out.cells[n] = g.cells[old];
    out.innerBary[n] = g.innerBary[old];
    for (int k = 0; k < 4; ++k) out.neighbours[n][std::size_t(k)] = newIndex[g.neighbours[old][std::size_t(k)]];
  }
  for (std::size_t n = 0; n < ns; ++n) {
    const std::uint32_t old = surfaceOrder[n];
    out.surfaceInner[n] = newIndex[g.surfaceInner[old]];
    out.surfaceSlot[n] = g.surfaceSlot[old];
    out.surfaceSource[n] = g.surfaceSource[old];
    out.surfaceBary[n] = g.surfaceBary[old];
  }
  out.updateGeometry();
  g = std::move(out);
}

/// Surface nodes in the order of their inner nodes.
inline std::vector<std::uint32_t> surfaceOrderFollowingInner(const QuadGraph& g, const std::vector<std::uint32_t>& innerOrder) {
  std::vector<std::uint32_t> rank(g.innerCount());
  for (std::size_t n = 0; n < innerOrder.size(); ++n) rank[innerOrder[n]] = std::uint32_t(n);
  std::vector<std::uint32_t> order(g.surfaceCount());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return rank[g.surfaceInner[a]] < rank[g.surfaceInner[b]]; });
  return order;
}

/// Fig. 7's greedy block fill. A block's traversal visits at most 8 r^2 nodes, so a region surrounded by
/// assigned nodes cannot make it quadratic; the next unassigned node then seeds a new block.
inline void packBlocks(QuadGraph& g, std::size_t blockSide = 32) {
  const std::size_t ni = g.innerCount(), blockSize = blockSide * blockSide;
  std::vector<std::uint32_t> order;
  order.reserve(ni);
  std::vector<char> assigned(ni, 0);
  std::vector<std::uint32_t> visitStamp(ni, 0);
  std::vector<std::uint32_t> queue;
  std::uint32_t stamp = 0;
  std::size_t nextSeed = 0;
  while (order.size() < ni) {
    while (assigned[nextSeed]) ++nextSeed;
    ++stamp;
    queue.assign(1, std::uint32_t(nextSeed));
    visitStamp[nextSeed] = stamp;
    std::size_t taken = 0;
    for (std::size_t head = 0; head < queue.size() && taken < blockSize && head < 8 * blockSize; ++head) {
      const std::uint32_t v = queue[head];
      if (!assigned[v]) assigned[v] = 1, order.push_back(v), ++taken;
      for (std::uint32_t w : g.neighbours[v])
        if (w < ni && visitStamp[w] != stamp) visitStamp[w] = stamp, queue.push_back(w);
    }
  }
  permuteNodes(g, order, surfaceOrderFollowingInner(g, order));
}

/// The baseline of Sec. 5.1: nodes in random order.
inline void shuffleNodes(QuadGraph& g, std::uint64_t seed = 1) {
  std::mt19937_64 rng(seed);
  std::vector<std::uint32_t> inner(g.innerCount()), surface(g.surfaceCount());
  std::iota(inner.begin(), inner.end(), 0u);
  std::iota(surface.begin(), surface.end(), 0u);
  std::shuffle(inner.begin(), inner.end(), rng);
  std::shuffle(surface.begin(), surface.end(), rng);
  permuteNodes(g, inner, surface);
}

}  // namespace lucent::quadgraph
