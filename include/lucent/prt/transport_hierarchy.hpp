#pragma once
/// @file transport_hierarchy.hpp
/// @brief Jensen and Buhler 2002's two-pass hierarchy in transport-vector space (Wang, Tran, Luebke
/// 2005, Sec. 3): the surface samples' area-weighted irradiance transport vectors A_j E_j (Haar,
/// sparse) go into an octree whose nodes hold the sum of their samples' vectors, truncated to a
/// bounded number of the largest coefficients (the paper's per-level truncation), their total area
/// and area-weighted centre. A point's multiple-scattering transport vector
///   T(x) = sum_j Rd(|x - x_j|) A_j E_j
/// descends the tree and takes a whole node as one source when its area over the squared distance
/// is below epsilon and x is outside its box (Jensen and Buhler's criterion); the sum is linear, so
/// clustering commutes with the wavelet transform. epsilon = 0 with every term kept is the exact
/// sum.
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

#include "../reference/point_octree.hpp"
#include "sparse_vector.hpp"

namespace lucent::prt {

class TransportHierarchy {
 public:
  /// @param weighted the samples' A_j E_j, Haar coefficients over a cube `faceSize` across
  /// @param nodeTerms coefficients a node keeps (0: all)
  TransportHierarchy(const std::vector<glm::dvec3>& positions, const std::vector<double>& areas,
                     std::vector<SparseScalars> weighted, int faceSize, std::size_t nodeTerms,
                     double epsilon, std::size_t leafSize = 8)
      : mPositions(positions),
        mSamples(std::move(weighted)),
        mTree(positions, leafSize),
        mEpsilon(epsilon) {
    const auto& nodes = mTree.nodes();
    mClusters.resize(nodes.size());
    std::vector<float> dense(std::size_t(6) * faceSize * faceSize, 0.0f);
    const std::size_t keep = nodeTerms == 0 ? dense.size() : nodeTerms;
    for (std::size_t index = nodes.size(); index-- > 0;) {  // children before parents
      const auto& node = nodes[index];
      Cluster& cluster = mClusters[index];
      glm::dvec3 weightedCentre(0);
      for (std::uint32_t k = node.begin; k < node.end; ++k) {
        const std::uint32_t i = mTree.order()[k];
        cluster.area += areas[i];
        weightedCentre += areas[i] * positions[i];
      }
      cluster.centre = cluster.area > 0 ? weightedCentre / cluster.area : 0.5 * (node.lo + node.hi);
      if (node.empty()) continue;
      if (node.leaf()) {
        for (std::uint32_t k = node.begin; k < node.end; ++k)
          add(mSamples[mTree.order()[k]], dense);
      } else {
        for (std::uint32_t c = 0; c < 8; ++c) add(mClusters[node.firstChild + c].transport, dense);
      }
      cluster.transport = keepLargest(dense, faceSize, keep);
      std::fill(dense.begin(), dense.end(), 0.0f);
    }
  }

  /// Adds T(x) per channel into `accumulator` (6 faceSize^2 RGB Haar coefficients); `rd(r)` is the
  /// profile R_d(r) per channel, taken as 0 beyond `reach` (nodes wholly farther are skipped).
  /// Returns how many vectors it added.
  template <class Rd>
  std::size_t gather(const glm::dvec3& x, const Rd& rd, std::vector<glm::vec3>& accumulator,
                     double reach = std::numeric_limits<double>::infinity()) const {
    const auto& nodes = mTree.nodes();
    if (nodes.empty()) return 0;
    std::size_t added = 0;
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
      const std::uint32_t index = stack.back();
      stack.pop_back();
      const auto& node = nodes[index];
      const Cluster& cluster = mClusters[index];
      const glm::dvec3 outside = glm::max(glm::max(node.lo - x, x - node.hi), glm::dvec3(0));
      if (glm::dot(outside, outside) > reach * reach) continue;
      const glm::dvec3 d = x - cluster.centre;
      const double dist2 = glm::dot(d, d);
      if (!node.contains(x) && cluster.area < mEpsilon * dist2) {
        addScaled(cluster.transport, glm::vec3(rd(std::sqrt(dist2))), accumulator), ++added;
      } else if (node.leaf()) {
        for (std::uint32_t k = node.begin; k < node.end; ++k) {
          const std::uint32_t i = mTree.order()[k];
          const double r = glm::length(x - mPositions[i]);
          if (r > reach) continue;
          addScaled(mSamples[i], glm::vec3(rd(r)), accumulator);
          ++added;
        }
      } else {
        for (std::uint32_t c = 0; c < 8; ++c)
          if (!nodes[node.firstChild + c].empty()) stack.push_back(node.firstChild + c);
      }
    }
    return added;
  }

  /// Adds sample i's vector A_i E_i times `scale` per channel (a near-field correction's terms).
  void addSample(std::size_t i, const glm::vec3& scale, std::vector<glm::vec3>& accumulator) const {
    addScaled(mSamples[i], scale, accumulator);
  }

  /// Bytes of the samples' and the nodes' sparse vectors (index + value each).
  std::size_t bytes() const {
    std::size_t terms = 0;
    for (const auto& s : mSamples) terms += s.size();
    for (const auto& c : mClusters) terms += c.transport.size();
    return terms * (sizeof(std::uint32_t) + sizeof(float));
  }
  std::size_t nodeCount() const { return mClusters.size(); }

 private:
  struct Cluster {
    glm::dvec3 centre{0};
    double area = 0;
    SparseScalars transport;
  };

  static void add(const SparseScalars& v, std::vector<float>& dense) {
    for (std::size_t i = 0; i < v.size(); ++i) dense[v.index[i]] += v.value[i];
  }
  static void addScaled(const SparseScalars& v, const glm::vec3& scale,
                        std::vector<glm::vec3>& dense) {
    for (std::size_t i = 0; i < v.size(); ++i) dense[v.index[i]] += scale * v.value[i];
  }

  std::vector<glm::dvec3> mPositions;
  std::vector<SparseScalars> mSamples;
  reference::PointOctree mTree;
  double mEpsilon;
  std::vector<Cluster> mClusters;
};

}  // namespace lucent::prt
