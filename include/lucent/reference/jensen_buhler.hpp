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
    mOrder.resize(n);
    std::iota(mOrder.begin(), mOrder.end(), 0);
    if (n == 0) return;
    glm::dvec3 lo = mPosition[0], hi = mPosition[0];
    for (const auto& p : mPosition) lo = glm::min(lo, p), hi = glm::max(hi, p);
    // A cube, so children are cubes too.
    const double half =
        0.5 * std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}) * (1 + 1e-9) + 1e-12;
    const glm::dvec3 c = 0.5 * (lo + hi);
    mNodes.resize(1);
    build(0, 0, n, c - half, c + half, 0);
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
    while (!stack.empty()) {
      const Node& node = mNodes[stack.back()];
      stack.pop_back();
      const glm::dvec3 d = xo - node.center;
      const double dist2 = glm::dot(d, d);
      const bool inside =
          glm::all(glm::greaterThanEqual(xo, node.lo)) && glm::all(glm::lessThanEqual(xo, node.hi));
      if (!inside && node.area < mEpsilon * dist2) {
        sum += node.power * glm::dvec3(profile.rd(T(std::sqrt(dist2))));
      } else if (node.firstChild == 0) {
        for (std::uint32_t k = node.begin; k < node.end; ++k) {
          const std::uint32_t i = mOrder[k];
          sum += mPower[i] * glm::dvec3(profile.rd(T(glm::length(xo - mPosition[i]))));
        }
      } else {
        for (int c = 0; c < 8; ++c)
          if (mNodes[node.firstChild + c].end > mNodes[node.firstChild + c].begin)
            stack.push_back(node.firstChild + c);
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
  struct Node {
    glm::dvec3 lo, hi, center, power{0};
    double area = 0;
    std::uint32_t begin = 0, end = 0,
                  firstChild = 0;  // firstChild 0: leaf (the root is never a child)
  };

  /// Fills the already allocated node `index`; children get 8 contiguous new slots, then recurse.
  /// No reference into mNodes is held across the recursion (the vector grows).
  void build(std::uint32_t index, std::size_t begin, std::size_t end, glm::dvec3 lo, glm::dvec3 hi,
             int depth) {
    Node node;
    node.lo = lo, node.hi = hi, node.begin = std::uint32_t(begin), node.end = std::uint32_t(end);
    glm::dvec3 weighted(0);
    double weight = 0;
    for (std::size_t k = begin; k < end; ++k) {
      const std::uint32_t i = mOrder[k];
      node.power += mPower[i];
      node.area += mArea[i];
      const double w = mPower[i].x + mPower[i].y + mPower[i].z;
      weighted += w * mPosition[i];
      weight += w;
    }
    node.center = weight > 0 ? weighted / weight : 0.5 * (lo + hi);
    const bool split = end - begin > mLeafSize && depth < 40;
    if (split) node.firstChild = std::uint32_t(mNodes.size());
    mNodes[index] = node;
    if (!split) return;
    mNodes.resize(mNodes.size() + 8);
    const glm::dvec3 mid = 0.5 * (lo + hi);
    // Partition this node's samples into octants, in place (stable within each octant).
    std::vector<std::uint32_t> bucket[8];
    for (std::size_t k = begin; k < end; ++k) {
      const glm::dvec3& p = mPosition[mOrder[k]];
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

  optics::Profile<T> mDipole;
  optics::Dipole<T> mPoles = mDipole.poles();  ///< the same, when it is a dipole
  const NearField* mNear;                      ///< the truth's, which outlives the tree
  double mEpsilon;
  std::size_t mLeafSize;
  std::vector<glm::dvec3> mPosition, mPower;
  std::vector<double> mArea;
  std::vector<std::uint32_t> mOrder;
  std::vector<Node> mNodes;
};

}  // namespace lucent::reference
