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
#include <cstdint>
#include <numeric>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "dipole_truth.hpp"
#include "point_octree.hpp"

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
  }

  /// B(xo) by the hierarchical approximation (Eq. 3 of Chang et al. 2008), with the
  /// truth's near field integrated as a disc (near_field.hpp; the samples within its radius are
  /// never clustered: a node there has area / distance^2 above any useful epsilon).
  glm::dvec3 radiosity(const glm::dvec3& xo) const {
    return treeSum(xo) + mNear->correction(xo, mDipole);
  }

  glm::dvec3 treeSum(const glm::dvec3& xo) const {
    // The dipoles' closed form directly: the profile's per-call dispatch would cost 3x per Rd.
    return mDipole.isPolePair() ? treeSumWith(xo, mPoles) : treeSumWith(xo, mDipole);
  }

  template <class Rd>
  glm::dvec3 treeSumWith(const glm::dvec3& xo, const Rd& profile) const {
    glm::dvec3 sum(0);
    if (mNodes.empty()) return sum;
    std::vector<std::uint32_t> stack{0};
    stack.reserve(64);
    const auto& nodes = mTree.nodes();
    const auto& order = mTree.order();
    while (!stack.empty()) {
      const std::uint32_t index = stack.back();
      stack.pop_back();
      const PointOctree::Node& node = nodes[index];
      const Cluster& cluster = mNodes[index];
      const glm::dvec3 d = xo - cluster.center;
      const double dist2 = glm::dot(d, d);
      if (!node.contains(xo) && cluster.area < mEpsilon * dist2) {
        sum += cluster.power * glm::dvec3(profile.rd(T(std::sqrt(dist2))));
      } else if (node.leaf()) {
        for (std::uint32_t k = node.begin; k < node.end; ++k) {
          const std::uint32_t i = order[k];
          sum += mPower[i] * glm::dvec3(profile.rd(T(glm::length(xo - mPosition[i]))));
        }
      } else {
        for (std::uint32_t c = 0; c < 8; ++c)
          if (!nodes[node.firstChild + c].empty()) stack.push_back(node.firstChild + c);
      }
    }
    return sum;
  }

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

  optics::Profile<T> mDipole;
  optics::Dipole<T> mPoles = mDipole.poles();  ///< the same, when it is a dipole
  const NearField* mNear;                      ///< the truth's, which outlives the tree
  double mEpsilon;
  std::size_t mLeafSize;
  std::vector<glm::dvec3> mPosition, mPower;
  std::vector<double> mArea;
  PointOctree mTree;
  std::vector<Cluster> mNodes;  ///< per node of mTree
};

}  // namespace lucent::reference
