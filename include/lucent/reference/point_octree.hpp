#pragma once
/// @file point_octree.hpp
/// @brief The octree of a point set that hierarchical sums cluster with (Jensen and Buhler 2002,
/// Sec. 3.2): a cube around the points, split into octants while a node holds more than a leaf's
/// worth. Nodes hold ranges of a permutation of the points; a node's children are 8 contiguous
/// nodes after it, so walking the nodes backwards visits every child before its parent.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace lucent::reference {

class PointOctree {
 public:
  struct Node {
    glm::dvec3 lo{0}, hi{0};
    std::uint32_t begin = 0, end = 0;
    std::uint32_t firstChild = 0;  ///< 0: a leaf (the root is never a child)
    bool leaf() const { return firstChild == 0; }
    bool empty() const { return end == begin; }
    bool contains(const glm::dvec3& p) const {
      return glm::all(glm::greaterThanEqual(p, lo)) && glm::all(glm::lessThanEqual(p, hi));
    }
  };

  PointOctree() = default;
  /// @param leafSize points a leaf may hold before it splits (at most 40 levels deep)
  PointOctree(const std::vector<glm::dvec3>& positions, std::size_t leafSize)
      : mPositions(&positions), mLeafSize(std::max<std::size_t>(1, leafSize)) {
    const std::size_t n = positions.size();
    mOrder.resize(n);
    std::iota(mOrder.begin(), mOrder.end(), 0);
    if (n == 0) return;
    glm::dvec3 lo = positions[0], hi = positions[0];
    for (const auto& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    // A cube, so children are cubes too.
    const double half =
        0.5 * std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}) * (1 + 1e-9) + 1e-12;
    const glm::dvec3 c = 0.5 * (lo + hi);
    mNodes.resize(1);
    build(0, 0, n, c - half, c + half, 0);
    mPositions = nullptr;  // only the build reads them
  }

  const std::vector<Node>& nodes() const { return mNodes; }
  /// The point indices, each node's a contiguous range [begin, end).
  const std::vector<std::uint32_t>& order() const { return mOrder; }

 private:
  /// Fills the already allocated node `index`; children get 8 contiguous new slots, then recurse.
  /// No reference into mNodes is held across the recursion (the vector grows).
  void build(std::uint32_t index, std::size_t begin, std::size_t end, glm::dvec3 lo, glm::dvec3 hi,
             int depth) {
    Node node;
    node.lo = lo, node.hi = hi, node.begin = std::uint32_t(begin), node.end = std::uint32_t(end);
    const bool split = end - begin > mLeafSize && depth < 40;
    if (split) node.firstChild = std::uint32_t(mNodes.size());
    mNodes[index] = node;
    if (!split) return;
    mNodes.resize(mNodes.size() + 8);
    const glm::dvec3 mid = 0.5 * (lo + hi);
    // Partition this node's points into octants, in place (stable within each octant).
    std::vector<std::uint32_t> bucket[8];
    for (std::size_t k = begin; k < end; ++k) {
      const glm::dvec3& p = (*mPositions)[mOrder[k]];
      bucket[int(p.x >= mid.x) | (int(p.y >= mid.y) << 1) | (int(p.z >= mid.z) << 2)].push_back(
          mOrder[k]);
    }
    std::size_t k = begin;
    for (int c = 0; c < 8; ++c) {
      const std::size_t childBegin = k;
      for (std::uint32_t i : bucket[c]) mOrder[k++] = i;
      const glm::dvec3 clo(c & 1 ? mid.x : lo.x, c & 2 ? mid.y : lo.y, c & 4 ? mid.z : lo.z);
      const glm::dvec3 chi(c & 1 ? hi.x : mid.x, c & 2 ? hi.y : mid.y, c & 4 ? hi.z : mid.z);
      build(node.firstChild + std::uint32_t(c), childBegin, k, clo, chi, depth + 1);
    }
  }

  const std::vector<glm::dvec3>* mPositions = nullptr;
  std::size_t mLeafSize = 8;
  std::vector<std::uint32_t> mOrder;
  std::vector<Node> mNodes;
};

}  // namespace lucent::reference
