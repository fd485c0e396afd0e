#pragma once
/// @file facet_adjacency.hpp
/// @brief Which triangle lies across each edge of a triangle soup: what a walk over a surface (the
/// manifold next-event search) steps along. Vertices are welded by exact position, since meshes
/// read from STL and the bodies of a MediumScene repeat them; an edge that is not shared by exactly
/// two triangles (a hole, a non-manifold fin) has no neighbour across it.
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <utility>
#include <vector>

#include "mesh.hpp"

namespace lucent::scene {

class FacetAdjacency {
 public:
  static constexpr std::uint32_t kNone = ~std::uint32_t(0);

  explicit FacetAdjacency(const TriangleMesh& mesh) : mAcross(3 * mesh.triangles.size(), kNone) {
    const std::vector<std::uint32_t> welded = weldedVertices(mesh);
    struct Uses {
      std::uint32_t first = kNone, second = kNone;  // slots 3 t + k
      int count = 0;
    };
    std::unordered_map<std::uint64_t, Uses> edges;
    edges.reserve(3 * mesh.triangles.size() / 2 + 1);
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        // Corner k's opposite edge joins the other two corners.
        std::uint64_t a = welded[mesh.triangles[t][(k + 1) % 3]];
        std::uint64_t b = welded[mesh.triangles[t][(k + 2) % 3]];
        if (a == b) continue;  // a degenerate triangle's collapsed edge
        if (a > b) std::swap(a, b);
        Uses& u = edges[(a << 32) | b];
        (u.count == 0 ? u.first : u.second) = 3 * t + std::uint32_t(k);
        ++u.count;
      }
    for (const auto& [key, u] : edges) {
      if (u.count != 2) continue;
      mAcross[u.first] = u.second / 3;
      mAcross[u.second] = u.first / 3;
    }
  }

  /// The triangle across the edge opposite corner k (0, 1, 2) of triangle t, or kNone.
  std::uint32_t across(std::uint32_t t, int k) const { return mAcross[3 * std::size_t(t) + k]; }

 private:
  static std::vector<std::uint32_t> weldedVertices(const TriangleMesh& mesh) {
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> buckets;
    std::vector<std::uint32_t> out(mesh.positions.size());
    buckets.reserve(mesh.positions.size());
    for (std::uint32_t i = 0; i < mesh.positions.size(); ++i) {
      const glm::vec3 p = mesh.positions[i] + glm::vec3(0.0f);  // -0 + 0 = +0: one hash for both
      std::uint32_t bits[3];
      std::memcpy(bits, &p, sizeof bits);
      const std::uint64_t hash = (std::uint64_t(bits[0]) * 0x9E3779B97F4A7C15ULL) ^
                                 (std::uint64_t(bits[1]) * 0xC2B2AE3D27D4EB4FULL) ^ bits[2];
      std::vector<std::uint32_t>& bucket = buckets[hash];
      out[i] = i;
      for (std::uint32_t j : bucket)
        if (mesh.positions[j] == p) {
          out[i] = j;
          break;
        }
      if (out[i] == i) bucket.push_back(i);
    }
    return out;
  }

  std::vector<std::uint32_t> mAcross;
};

}  // namespace lucent::scene
