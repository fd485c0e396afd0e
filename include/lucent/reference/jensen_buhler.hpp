#pragma once
/// @file jensen_buhler.hpp
/// @brief Jensen and Buhler 2002, "A Rapid Hierarchical Rendering Technique for Translucent
/// Materials": the irradiance samples go into an octree whose nodes store their total power sum E_i
/// A_i, total area and power-weighted position; B(xo) descends the tree and uses a whole node as
/// one source when it is small as seen from xo, i.e. its area over squared distance is below the
/// error bound epsilon (their Sec. 3.2 criterion), and xo is outside its box. epsilon = 0 visits
/// every sample: the exact sum. Chang et al. 2008 used it as ground truth and speed
/// baseline.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <numeric>
#include <type_traits>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "dipole_truth.hpp"
#include "point_octree.hpp"
#include "rd_sum_kernel.hpp"

namespace lucent::reference {

template <class T>
class JensenBuhlerTree {
 public:
  /// @param maxLeafSamples samples a leaf may hold before it splits
  explicit JensenBuhlerTree(const DipoleTruth<T>& truth, double epsilon,
                            std::size_t maxLeafSamples = 8)
      : mDipole(truth.profile()),
        mNear(&truth.nearField()),
        mEpsilon(epsilon),
        mLeafSize(std::max<std::size_t>(1, maxLeafSamples)) {
    const std::size_t n = truth.litCount();
    mPosition.resize(n);
    mPower.resize(n);
    mArea.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      mPosition[i] = truth.litPosition(i);
      mPower[i] = truth.litPower(i);
      mArea[i] = truth.litArea(i);
    }
    mTree = PointOctree(mPosition, mLeafSize);
    // Each node as one source: total power and area, power-weighted centre (children first).
    const auto& nodes = mTree.nodes();
    mNodes.resize(nodes.size());
    for (std::size_t index = nodes.size(); index-- > 0;) {
      const PointOctree::Node& topology = nodes[index];
      Cluster& cluster = mNodes[index];
      glm::dvec3 weighted(0);
      double weight = 0;
      for (std::uint32_t k = topology.begin; k < topology.end; ++k) {
        const std::uint32_t i = mTree.order()[k];
        cluster.power += mPower[i];
        cluster.area += mArea[i];
        const double w = mPower[i].x + mPower[i].y + mPower[i].z;
        weighted += w * mPosition[i];
        weight += w;
      }
      cluster.center = weight > 0 ? weighted / weight : 0.5 * (topology.lo + topology.hi);
    }
    if (std::is_same_v<T, float> && mDipole.isPolePair()) {  // treeSumVectorised's copy
      for (auto& a : mOrdered.array) a.resize(n);
      for (std::size_t k = 0; k < n; ++k)
        mOrdered.set(k, mPosition[mTree.order()[k]], mPower[mTree.order()[k]]);
    }
  }

  /// B(xo) by the hierarchical approximation (Eq. 3 of Chang et al. 2008), with the
  /// truth's near field integrated as a disc (near_field.hpp; the samples within its radius are
  /// never clustered: a node there has area / distance^2 above any useful epsilon).
  glm::dvec3 radiosity(const glm::dvec3& xo) const {
    return treeSum(xo) + mNear->correction(xo, mDipole);
  }

  glm::dvec3 treeSum(const glm::dvec3& xo) const {
    if constexpr (std::is_same_v<T, float>)
      if (mDipole.isPolePair()) return treeSumVectorised(xo);
    // The dipoles' closed form directly: the profile's per-call dispatch would cost 3x per Rd.
    return mDipole.isPolePair() ? treeSumWith(xo, mPoles) : treeSumWith(xo, mDipole);
  }

  /// The sum one Rd at a time, in T.
  template <class Rd>
  glm::dvec3 treeSumWith(const glm::dvec3& xo, const Rd& profile) const {
    glm::dvec3 sum(0);
    auto add = [&](const glm::dvec3& x, const glm::dvec3& power) {
      sum += power * glm::dvec3(profile.rd(T(glm::length(xo - x))));
    };
    const std::size_t terms = traverse(
        xo, [&](const Cluster& c) { add(c.center, c.power); },
        [&](std::uint32_t begin, std::uint32_t end) {
          for (std::uint32_t k = begin; k < end; ++k)
            add(mPosition[mTree.order()[k]], mPower[mTree.order()[k]]);
        });
    mTerms->fetch_add(terms, std::memory_order_relaxed);
    return sum;
  }

  /// The same sources gathered into float arrays and summed by the truth's vectorised kernel
  /// (rd_sum_kernel.hpp), so that the octree is measured with the same leaf kernel as the
  /// techniques it is the baseline of. A leaf's samples are one range of arrays kept in tree
  /// order, copied whole.
  glm::dvec3 treeSumVectorised(const glm::dvec3& xo) const {
    thread_local GatheredSamples gathered;
    std::size_t n = 0;
    const std::size_t terms = traverse(
        xo,
        [&](const Cluster& c) {
          gathered.fit(n + 1);
          gathered.set(n++, c.center, c.power);
        },
        [&](std::uint32_t begin, std::uint32_t end) {
          gathered.fit(n + (end - begin));
          for (int a = 0; a < GatheredSamples::kArrays; ++a)
            std::copy(mOrdered.array[a].begin() + begin, mOrdered.array[a].begin() + end,
                      gathered.array[a].begin() + std::ptrdiff_t(n));
          n += end - begin;
        });
    mTerms->fetch_add(terms, std::memory_order_relaxed);
    double out[3];
    rdSumFloat(gathered.view(n), mKernel, float(xo.x), float(xo.y), float(xo.z), out);
    return {out[0], out[1], out[2]};
  }

  /// Rd terms summed so far (leaf samples and whole nodes), for the stage's rate.
  std::uint64_t termCount() const { return mTerms->load(std::memory_order_relaxed); }

  glm::dvec3 radiance(const glm::dvec3& xo, double cosOut) const {
    return radiosity(xo) * (optics::fresnelTransmittance(cosOut, double(mDipole.eta)) *
                            double(mDipole.exitScale) / optics::kPi);
  }

  std::size_t nodeCount() const { return mNodes.size(); }

 private:
  /// A node as one source.
  struct Cluster {
    glm::dvec3 center{0}, power{0};
    double area = 0;
  };

  /// Descends the tree for x_o: onNode(cluster) for a node small as seen from x_o (the file
  /// comment's criterion), onLeaf(begin, end) for a leaf's samples (a range in tree order)
  /// otherwise. Returns the number of sources visited.
  template <class OnNode, class OnLeaf>
  std::size_t traverse(const glm::dvec3& xo, OnNode&& onNode, OnLeaf&& onLeaf) const {
    if (mNodes.empty()) return 0;
    thread_local std::vector<std::uint32_t> stack;
    stack.assign(1, 0);
    const auto& nodes = mTree.nodes();
    std::size_t visited = 0;
    while (!stack.empty()) {
      const std::uint32_t index = stack.back();
      stack.pop_back();
      const PointOctree::Node& node = nodes[index];
      const Cluster& cluster = mNodes[index];
      const glm::dvec3 d = xo - cluster.center;
      if (!node.contains(xo) && cluster.area < mEpsilon * glm::dot(d, d)) {
        onNode(cluster), ++visited;
      } else if (node.leaf()) {
        onLeaf(node.begin, node.end), visited += node.end - node.begin;
      } else {
        for (std::uint32_t c = 0; c < 8; ++c)
          if (!nodes[node.firstChild + c].empty()) stack.push_back(node.firstChild + c);
      }
    }
    return visited;
  }

  optics::Profile<T> mDipole;
  optics::Dipole<T> mPoles = mDipole.poles();  ///< the same, when it is a dipole
  const NearField* mNear;                      ///< the truth's, which outlives the tree
  double mEpsilon;
  std::size_t mLeafSize;
  std::vector<glm::dvec3> mPosition, mPower;
  std::vector<double> mArea;
  PointOctree mTree;
  std::vector<Cluster> mNodes;  ///< per node of mTree
  GatheredSamples mOrdered;     ///< the samples in tree order, for treeSumVectorised
  RdKernelConstants mKernel =
      mDipole.isPolePair() ? RdKernelConstants::from(mDipole) : RdKernelConstants{};
  /// Behind a pointer: the tree stays movable.
  std::unique_ptr<std::atomic<std::uint64_t>> mTerms =
      std::make_unique<std::atomic<std::uint64_t>>(0);
};

}  // namespace lucent::reference
