#pragma once
/// @file shapes.hpp
/// @brief Closed, outward-oriented parametric shapes (unit-ish size; scale with TriangleMesh::scaleToSize).
/// The implicit ones (double torus, genus 7) need a contouring filter and live in src/scene.
#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "../optics/constants.hpp"
#include "mesh.hpp"

namespace lucent::scene::shapes {

namespace detail {
/// Adds the quad grid (rows x cols) given by vertex indices idx(i, j), as two triangles per cell.
template <class Index>
void addGrid(TriangleMesh& m, int rows, int cols, Index idx) {
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const unsigned a = idx(i, j), b = idx(i + 1, j), c = idx(i + 1, j + 1), d = idx(i, j + 1);
      m.triangles.push_back({a, b, c});
      m.triangles.push_back({a, c, d});
    }
}

inline void flip(TriangleMesh& m, std::size_t firstTriangle) {
  for (std::size_t t = firstTriangle; t < m.triangles.size(); ++t) std::swap(m.triangles[t].y, m.triangles[t].z);
}

/// Orients every triangle of the mesh outward if the whole mesh currently points inward.
inline void orientOutward(TriangleMesh& m) {
  if (m.signedVolume() < 0) flip(m, 0);
}
}  // namespace detail

/// Icosphere: the icosahedron subdivided `levels` times and projected onto the sphere.
inline TriangleMesh sphere(double radius = 1.0, int levels = 4, glm::dvec3 center = glm::dvec3(0)) {
  TriangleMesh m;
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  const double v[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                           {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  const unsigned f[20][3] = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                             {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                             {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  std::vector<glm::dvec3> p;
  for (const auto& q : v) p.push_back(glm::normalize(glm::dvec3(q[0], q[1], q[2])));
  std::vector<glm::uvec3> tris;
  for (const auto& q : f) tris.push_back({q[0], q[1], q[2]});
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<unsigned, unsigned>, unsigned> mid;
    auto midpoint = [&](unsigned a, unsigned b) {
      const auto key = std::minmax(a, b);
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      p.push_back(glm::normalize(p[a] + p[b]));
      return mid[key] = unsigned(p.size() - 1);
    };
    std::vector<glm::uvec3> next;
    for (const auto& tri : tris) {
      const unsigned a = midpoint(tri.x, tri.y), b = midpoint(tri.y, tri.z), c = midpoint(tri.z, tri.x);
      next.push_back({tri.x, a, c});
      next.push_back({tri.y, b, a});
      next.push_back({tri.z, c, b});
      next.push_back({a, b, c});
    }
    tris.swap(next);
  }
  for (const auto& q : p) m.positions.push_back(glm::vec3(center + radius * q));
  m.triangles = tris;
  detail::orientOutward(m);
  return m;
}

/// Torus around the y axis: ring radius R, tube radius r.
inline TriangleMesh torus(double R = 1.0, double r = 0.4, int ringSegments = 96, int tubeSegments = 48) {
  TriangleMesh m;
  for (int i = 0; i < ringSegments; ++i)
    for (int j = 0; j < tubeSegments; ++j) {
      const double u = 2 * optics::kPi * i / ringSegments, v = 2 * optics::kPi * j / tubeSegments;
      const double w = R + r * std::cos(v);
      m.positions.push_back(glm::vec3(w * std::cos(u), r * std::sin(v), w * std::sin(u)));
    }
  detail::addGrid(m, ringSegments, tubeSegments,
                  [&](int i, int j) { return unsigned((i % ringSegments) * tubeSegments + (j % tubeSegments)); });
  detail::orientOutward(m);
  return m;
}

/// A box [-sx,sx]x[-sy,sy]x[-sz,sz] with each face split into cells no longer than `cell`.
inline TriangleMesh box(glm::dvec3 half, double cell) {
  TriangleMesh m;
  const glm::ivec3 n = glm::max(glm::ivec3(1), glm::ivec3(glm::ceil(2.0 * half / cell)));
  // Vertices live on an integer lattice; the map welds the ones faces share along edges and corners.
  std::map<std::tuple<int, int, int>, unsigned> index;
  auto vertex = [&](glm::ivec3 q) {
    const auto key = std::make_tuple(q.x, q.y, q.z);
    const auto it = index.find(key);
    if (it != index.end()) return it->second;
    m.positions.push_back(glm::vec3(-half + 2.0 * half * glm::dvec3(q) / glm::dvec3(n)));
    return index[key] = unsigned(m.positions.size() - 1);
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int a = (axis + 1) % 3, b = (axis + 2) % 3;
      const std::size_t first = m.triangles.size();
      detail::addGrid(m, n[a], n[b], [&](int i, int j) {
        glm::ivec3 q;
        q[axis] = side * n[axis];
        q[a] = i;
        q[b] = j;
        return vertex(q);
      });
      // (a, b, axis) is right-handed: the grid's triangles face +axis; flip those on the - side.
      if (side == 0) detail::flip(m, first);
    }
  return m;
}

/// A thin slab: a square plate of side 1 and the given thickness.
inline TriangleMesh slab(double thickness = 0.1, double cell = 0.02) {
  return box(glm::dvec3(0.5, 0.5, 0.5 * thickness), cell);
}

/// A cube of side 2 with a concentric spherical cavity of the given radius (faces point into the cavity).
inline TriangleMesh cubeWithCavity(double cavityRadius = 0.6) {
  TriangleMesh m = box(glm::dvec3(1.0), 0.1);
  const TriangleMesh cavity = sphere(cavityRadius, 4);
  const unsigned offset = unsigned(m.positions.size());
  m.positions.insert(m.positions.end(), cavity.positions.begin(), cavity.positions.end());
  for (const auto& t : cavity.triangles) m.triangles.push_back({t.x + offset, t.z + offset, t.y + offset});
  return m;
}

/// "Twirl": a thin ribbon of width w and thickness d along y, twisted by `turns` full turns.
inline TriangleMesh twirl(double length = 2.0, double width = 0.5, double thickness = 0.04, double turns = 0.75,
                          int lengthSegments = 160, int edgeSegments = 24) {
  TriangleMesh m;
  // The cross-section's perimeter: 4 sides, each split into segments proportional to its length.
  const int thin = std::max(1, int(edgeSegments * thickness / width));
  const int sides[4] = {edgeSegments, thin, edgeSegments, thin};
  std::vector<glm::dvec2> ring;
  const glm::dvec2 corner[4] = {{-width / 2, -thickness / 2}, {width / 2, -thickness / 2}, {width / 2, thickness / 2},
                                {-width / 2, thickness / 2}};
  for (int s = 0; s < 4; ++s)
    for (int k = 0; k < sides[s]; ++k) ring.push_back(glm::mix(corner[s], corner[(s + 1) % 4], double(k) / sides[s]));
  const int perimeter = int(ring.size());
  for (int i = 0; i <= lengthSegments; ++i) {
    const double y = -length / 2 + length * i / lengthSegments;
    const double angle = 2 * optics::kPi * turns * i / lengthSegments;
    const double c = std::cos(angle), s = std::sin(angle);
    for (const auto& q : ring) m.positions.push_back(glm::vec3(c * q.x - s * q.y, y, s * q.x + c * q.y));
  }
  detail::addGrid(m, lengthSegments, perimeter,
                  [&](int i, int j) { return unsigned(i * perimeter + (j % perimeter)); });
  for (int end = 0; end < 2; ++end) {  // caps: a fan around each end's centre
    const int row = end * lengthSegments;
    m.positions.push_back(glm::vec3(0, end ? length / 2 : -length / 2, 0));
    const unsigned center = unsigned(m.positions.size() - 1);
    for (int j = 0; j < perimeter; ++j) {
      const unsigned a = unsigned(row * perimeter + j), b = unsigned(row * perimeter + (j + 1) % perimeter);
      if (end) m.triangles.push_back({center, b, a});
      else m.triangles.push_back({center, a, b});
    }
  }
  detail::orientOutward(m);
  return m;
}

}  // namespace lucent::scene::shapes
