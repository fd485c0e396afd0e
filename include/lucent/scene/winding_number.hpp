#pragma once
/// @file winding_number.hpp
/// @brief The generalized winding number of a triangle soup (Jacobson, Kavan, Sorkine-Hornung 2013,
/// Eq. 4: the signed solid angles of the triangles over 4 pi) and the distance to it, over one
/// bounding-volume hierarchy. Far clusters enter by their multipole expansion to second order
/// (Barill, Dickson, Schmidt, Levin, Jacobson 2018, Sec. 3.2: dipole plus the gradient term),
/// near ones triangle by triangle. The winding number is 1 inside a closed, outward surface
/// and 0 outside, and degrades gracefully with holes, flips, overlaps and non-manifold parts: the
/// inside/outside field a robust repair re-extracts.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "mesh.hpp"

namespace lucent::scene {

namespace detail {
/// The signed solid angle of triangle abc seen from the origin (Van Oosterom & Strackee 1983):
/// positive when the triangle winds counter-clockwise seen from the origin's far side.
inline double solidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
  const double numerator = glm::dot(a, glm::cross(b, c));
  // In the triangle's plane the angle jumps between -2 pi and 2 pi (atan2's branch by the sign of a
  // zero): a point on the surface gets 0 from it, so an open sheet's own points are not inside.
  if (numerator == 0) return 0;
  const double denominator =
      la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
  return 2.0 * std::atan2(numerator, denominator);
}

/// The point of segment ab nearest to p (a point when a == b).
inline glm::dvec3 closestOnSegment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  return len2 > 0 ? a + ab * std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : a;
}

/// The point of triangle abc nearest to p (Ericson, Real-Time Collision Detection, 5.1.5); of its
/// edges when it has no area (the regions' divisions would be 0 / 0).
inline glm::dvec3 closestOnTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                    const glm::dvec3& c) {
  const glm::dvec3 n = glm::cross(b - a, c - a);
  if (!(glm::dot(n, n) > 0)) {
    const glm::dvec3 e[3] = {closestOnSegment(p, a, b), closestOnSegment(p, b, c),
                             closestOnSegment(p, c, a)};
    auto d2 = [&](const glm::dvec3& q) { return glm::dot(q - p, q - p); };
    return d2(e[0]) <= d2(e[1]) ? (d2(e[0]) <= d2(e[2]) ? e[0] : e[2])
                                : (d2(e[1]) <= d2(e[2]) ? e[1] : e[2]);
  }
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = va + vb + vc;
  if (!(std::fabs(denom) > 0)) return a;  // a degenerate triangle: its first corner
  return a + ab * (vb / denom) + ac * (vc / denom);
}
}  // namespace detail

class TriangleSoupField {
 public:
  /// Clusters farther than this many cluster radii enter by their expansion (Barill et al. 2018
  /// use 2; at 3 with the second-order term the winding number is within 2e-2 of the plain sum,
  /// tests/unit/test_winding_number.cpp, and a repair thresholds it at 1/2).
  static constexpr double kFarRatio = 3.0;

  /// `mesh` must outlive the field (it is read, not copied).
  explicit TriangleSoupField(const TriangleMesh& mesh) : mMesh(mesh) {
    mOrder.resize(mesh.triangles.size());
    std::iota(mOrder.begin(), mOrder.end(), std::uint32_t(0));
    mCentroids.reserve(mOrder.size());
    for (std::size_t t = 0; t < mOrder.size(); ++t)
      mCentroids.push_back((corner(t, 0) + corner(t, 1) + corner(t, 2)) / 3.0);
    if (mOrder.empty()) return;
    mNodes.resize(1);
    build(0, 0, std::uint32_t(mOrder.size()));
  }
  TriangleSoupField(TriangleMesh&&) = delete;

  /// The generalized winding number at p: the triangles' solid angles over 4 pi.
  double windingNumber(const glm::dvec3& p) const {
    if (mNodes.empty()) return 0;
    double sum = 0;
    Stack stack;
    while (!stack.empty()) {
      const Node& n = mNodes[stack.pop()];
      const glm::dvec3 toCentre = n.centre - p;
      const double d2 = glm::dot(toCentre, toCentre);
      if (d2 > kFarRatio * kFarRatio * n.radius * n.radius) {
        sum += farField(n, toCentre, d2);
      } else if (n.count > 0) {
        for (std::uint32_t i = n.first; i < n.first + n.count; ++i)
          sum += detail::solidAngle(corner(mOrder[i], 0) - p, corner(mOrder[i], 1) - p,
                                    corner(mOrder[i], 2) - p);
      } else {
        stack.push(n.first), stack.push(n.first + 1);
      }
    }
    return sum / (4.0 * 3.14159265358979323846);
  }

  /// The distance from p to the nearest triangle (infinity for an empty soup).
  double distance(const glm::dvec3& p) const {
    double best2 = std::numeric_limits<double>::infinity();
    if (mNodes.empty()) return best2;
    Stack stack;
    while (!stack.empty()) {
      const Node& n = mNodes[stack.pop()];
      const glm::dvec3 gap = glm::max(glm::max(n.lo - p, p - n.hi), glm::dvec3(0));
      if (glm::dot(gap, gap) >= best2) continue;
      if (n.count == 0) {
        stack.push(n.first), stack.push(n.first + 1);
        continue;
      }
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        const auto t = mOrder[i];
        const glm::dvec3 q =
            detail::closestOnTriangle(p, corner(t, 0), corner(t, 1), corner(t, 2)) - p;
        best2 = std::min(best2, glm::dot(q, q));
      }
    }
    return std::sqrt(best2);
  }

 private:
  static constexpr std::uint32_t kLeafSize = 8;
  /// Nodes still to visit, depth first; no allocation per query. A median split halves every level,
  /// so the tree is at most 30 deep for 2^32 triangles and the stack holds at most one node a level
  /// plus one.
  struct Stack {
    std::array<std::uint32_t, 96> items{};
    int size = 1;  // starts with the root, node 0
    bool empty() const { return size == 0; }
    void push(std::uint32_t i) { items[std::size_t(size++)] = i; }
    std::uint32_t pop() { return items[std::size_t(--size)]; }
  };
  /// A cluster: `count` triangles from mOrder[first] (a leaf), or children first and first + 1.
  struct Node {
    glm::dvec3 lo{0}, hi{0};   ///< bounds of its triangles' corners
    glm::dvec3 centre{0};      ///< area-weighted centroid
    glm::dvec3 areaVector{0};  ///< sum of area times unit normal
    glm::dmat3 moment{0.0};    ///< sum of area vector (x) (centroid - centre), see farField
    double radius = 0;         ///< from centre to its farthest corner
    std::uint32_t first = 0, count = 0;
  };

  /// A cluster's solid angle from y = centre - p: the dipole N.y/|y|^3 plus the gradient term
  /// sum_jk M_jk (delta_jk/|y|^3 - 3 y_j y_k/|y|^5), M_jk = sum a n_j (x - centre)_k (exact for
  /// flat triangles: the moment is linear in x).
  static double farField(const Node& n, const glm::dvec3& y, double d2) {
    const double inv3 = 1.0 / (d2 * std::sqrt(d2)), inv5 = inv3 / d2;
    const double trace = n.moment[0][0] + n.moment[1][1] + n.moment[2][2];
    const glm::dvec3 my = n.moment * y;  // glm is column-major: (M y)_j = sum_k M[k][j] y_k
    return glm::dot(n.areaVector, y) * inv3 + trace * inv3 - 3.0 * glm::dot(y, my) * inv5;
  }

  glm::dvec3 corner(std::size_t t, int k) const {
    return glm::dvec3(mMesh.positions[mMesh.triangles[t][k]]);
  }

  /// Fills node `index` with mOrder[begin, end) and, below it, its children (median split along
  /// the widest axis of the centroids). Children sit side by side: a node keeps the first's index.
  void build(std::uint32_t index, std::uint32_t begin, std::uint32_t end) {
    mNodes[index] = summarise(begin, end);
    if (end - begin <= kLeafSize) {
      mNodes[index].first = begin, mNodes[index].count = end - begin;
      return;
    }
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (std::uint32_t i = begin; i < end; ++i)
      lo = glm::min(lo, mCentroids[mOrder[i]]), hi = glm::max(hi, mCentroids[mOrder[i]]);
    const glm::dvec3 extent = hi - lo;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t middle = begin + (end - begin) / 2;
    std::nth_element(mOrder.begin() + begin, mOrder.begin() + middle, mOrder.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) {
                       return mCentroids[a][axis] < mCentroids[b][axis];
                     });
    const auto left = std::uint32_t(mNodes.size());
    mNodes.resize(mNodes.size() + 2);
    mNodes[index].first = left;
    build(left, begin, middle);
    build(left + 1, middle, end);
  }

  Node summarise(std::uint32_t begin, std::uint32_t end) const {
    Node n;
    n.lo = glm::dvec3(std::numeric_limits<double>::infinity()), n.hi = -n.lo;
    double area = 0;
    glm::dvec3 weighted(0);
    for (std::uint32_t i = begin; i < end; ++i) {
      const auto t = mOrder[i];
      const glm::dvec3 a = corner(t, 0), b = corner(t, 1), c = corner(t, 2);
      const glm::dvec3 areaVector = 0.5 * glm::cross(b - a, c - a);
      const double ai = glm::length(areaVector);
      n.areaVector += areaVector, area += ai, weighted += ai * mCentroids[t];
      n.lo = glm::min(n.lo, glm::min(a, glm::min(b, c)));
      n.hi = glm::max(n.hi, glm::max(a, glm::max(b, c)));
    }
    n.centre = area > 0 ? weighted / area : 0.5 * (n.lo + n.hi);
    for (std::uint32_t i = begin; i < end; ++i) {
      const auto t = mOrder[i];
      const glm::dvec3 a = corner(t, 0), b = corner(t, 1), c = corner(t, 2);
      // glm's outerProduct(c, r) is c r^T: element [k][j] = c_j r_k, so moment[k][j] = N_j x_k.
      n.moment += glm::outerProduct(0.5 * glm::cross(b - a, c - a), mCentroids[t] - n.centre);
      for (int k = 0; k < 3; ++k)
        n.radius = std::max(n.radius, glm::length(corner(t, k) - n.centre));
    }
    return n;
  }

  const TriangleMesh& mMesh;
  std::vector<std::uint32_t> mOrder;
  std::vector<glm::dvec3> mCentroids;
  std::vector<Node> mNodes;
};

}  // namespace lucent::scene
