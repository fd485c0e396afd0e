#pragma once
/// @file texture_atlas.hpp
/// @brief The texture atlas of Chang et al. 2008 Sec. 2.2: every triangle gets texture
/// coordinates, charts are packed without overlap with empty gutter texels between them, and each texel
/// centre is owned by at most one triangle (the one a GPU rasteriser would draw there).
///
/// Any parameterization is correct because irradiance is stored as E' = E A_S/A_T (Eq. 6-7). Here A_T is
/// the triangle's rasterised texel count (times the texel area), so the atlas integral of E' equals the
/// surface integral of E whatever the chart distortion or the texel size; a triangle too small to own
/// a texel centre lends its area to the texel under its centroid ("guest"), displacing it by < 1 texel.
///
/// Built-in parameterization: normal-cone charts (chart_segmentation.hpp), projected orthographically
/// (area kept within cos of the cone angle), packed with one scale for all charts. Charts that fold
/// onto themselves (detected as two triangles owning one texel) are cut again with half the angle.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "../optics/constants.hpp"
#include "chart_segmentation.hpp"
#include "shelf_packing.hpp"

namespace lucent::atlas {

struct AtlasOptions {
  int resolution = 1024;         ///< texels per side
  double maxNormalAngleDeg = 40; ///< chart cone half-angle
  int gutter = 2;                ///< empty texels around each chart (room for bilinear filtering on a GPU)
  int maxRecuts = 8;             ///< rounds of re-cutting folded charts
};

struct AtlasStats {
  int charts = 0;
  int recutRounds = 0;              ///< rounds needed until no chart folded
  double coverage = 0;              ///< fraction of texels owned by a triangle
  double texelsPerMm = 0;           ///< scale of the packing (built-in parameterization)
  double areaStretchMin = 0;        ///< min over triangles of (A_T / A_S) / (total A_T / total A_S)
  double areaStretchMax = 0;        ///< max of the same: 1 everywhere is perfectly area-preserving
  std::size_t guestTriangles = 0;   ///< triangles owning no texel centre (carried by a neighbour texel)
  double guestAreaFraction = 0;     ///< their share of the surface area
};

struct TextureAtlas {
  int resolution = 0;
  std::vector<glm::dvec2> uv;               ///< 3 per triangle, in texels: texel (x, y) spans [x, x+1) x [y, y+1)
  std::vector<int> chartOfTriangle;         ///< -1 for degenerate triangles
  std::vector<std::int32_t> texelTriangle;  ///< resolution^2, row-major; owning triangle or -1
  std::vector<std::uint32_t> texelCount;    ///< per triangle: texels it owns (0 for a guest)
  std::vector<std::int32_t> guestTexel;     ///< per triangle: the texel a guest is carried by, else -1
  AtlasStats stats;

  std::size_t texelIndex(int x, int y) const { return std::size_t(y) * std::size_t(resolution) + std::size_t(x); }
};

namespace detail {

/// 2-D orientation of p against the edge u -> v, computed in a canonical vertex order so that the two
/// triangles sharing an edge get exactly opposite values (no texel is claimed twice by rounding).
inline double edgeFunction(const glm::dvec2& u, const glm::dvec2& v, const glm::dvec2& p) {
  const bool swapped = v.x < u.x || (v.x == u.x && v.y < u.y);
  const glm::dvec2& a = swapped ? v : u;
  const glm::dvec2& b = swapped ? u : v;
  const double e = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
  return swapped ? -e : e;
}

/// Fill rule for points exactly on an edge: of the two directions of an edge exactly one owns it.
inline bool ownsEdge(const glm::dvec2& u, const glm::dvec2& v) {
  const double dy = v.y - u.y, dx = v.x - u.x;
  return dy > 0 || (dy == 0 && dx < 0);
}

inline bool insideTriangle(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& p) {
  const double w[3] = {edgeFunction(b, c, p), edgeFunction(c, a, p), edgeFunction(a, b, p)};
  const glm::dvec2* e[3][2] = {{&b, &c}, {&c, &a}, {&a, &b}};
  for (int k = 0; k < 3; ++k)
    if (w[k] < 0 || (w[k] == 0 && !ownsEdge(*e[k][0], *e[k][1]))) return false;
  return true;
}

inline double signedArea2(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/// Rasterises all triangles into atlas.texelTriangle; returns the charts in which two triangles claimed
/// the same texel (the chart folds over itself or, for user UVs, islands overlap).
inline std::vector<int> rasterize(const scene::TriangleMesh& mesh, TextureAtlas& atlas) {
  const int res = atlas.resolution;
  atlas.texelTriangle.assign(std::size_t(res) * res, -1);
  atlas.texelCount.assign(mesh.triangles.size(), 0);
  atlas.guestTexel.assign(mesh.triangles.size(), -1);
  std::vector<int> folded;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (atlas.chartOfTriangle[t] < 0) continue;
    glm::dvec2 a = atlas.uv[3 * t], b = atlas.uv[3 * t + 1], c = atlas.uv[3 * t + 2];
    if (signedArea2(a, b, c) < 0) std::swap(b, c);  // user UVs may be mirrored; the fill rule needs CCW
    const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x}) - 0.5)));
    const int x1 = std::min(res - 1, int(std::ceil(std::max({a.x, b.x, c.x}) - 0.5)));
    const int y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y}) - 0.5)));
    const int y1 = std::min(res - 1, int(std::ceil(std::max({a.y, b.y, c.y}) - 0.5)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        if (!insideTriangle(a, b, c, {x + 0.5, y + 0.5})) continue;
        std::int32_t& owner = atlas.texelTriangle[atlas.texelIndex(x, y)];
        if (owner >= 0) {
          folded.push_back(atlas.chartOfTriangle[t]);
          folded.push_back(atlas.chartOfTriangle[std::size_t(owner)]);
          continue;
        }
        owner = std::int32_t(t);
        ++atlas.texelCount[t];
      }
  }
  std::sort(folded.begin(), folded.end());
  folded.erase(std::unique(folded.begin(), folded.end()), folded.end());
  return folded;
}

/// Triangles that own no texel: claim the free texel under the centroid, else ride on its owner.
inline void placeGuests(const scene::TriangleMesh& mesh, TextureAtlas& atlas) {
  const int res = atlas.resolution;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (atlas.chartOfTriangle[t] < 0 || atlas.texelCount[t] > 0) continue;
    const glm::dvec2 centroid = (atlas.uv[3 * t] + atlas.uv[3 * t + 1] + atlas.uv[3 * t + 2]) / 3.0;
    const int x = std::clamp(int(std::floor(centroid.x)), 0, res - 1);
    const int y = std::clamp(int(std::floor(centroid.y)), 0, res - 1);
    std::int32_t& owner = atlas.texelTriangle[atlas.texelIndex(x, y)];
    if (owner < 0) {
      owner = std::int32_t(t);
      atlas.texelCount[t] = 1;
    } else {
      atlas.guestTexel[t] = std::int32_t(atlas.texelIndex(x, y));
    }
  }
}

inline void computeStats(const scene::TriangleMesh& mesh, TextureAtlas& atlas) {
  AtlasStats& s = atlas.stats;
  double totalS = 0, totalT = 0, guestArea = 0;
  std::vector<double> as(mesh.triangles.size(), 0), at(mesh.triangles.size(), 0);
  s.guestTriangles = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (atlas.chartOfTriangle[t] < 0) continue;
    as[t] = mesh.triangleArea(t);
    at[t] = 0.5 * std::abs(signedArea2(atlas.uv[3 * t], atlas.uv[3 * t + 1], atlas.uv[3 * t + 2]));
    totalS += as[t];
    totalT += at[t];
    if (atlas.guestTexel[t] >= 0) ++s.guestTriangles, guestArea += as[t];
  }
  s.areaStretchMin = std::numeric_limits<double>::infinity();
  s.areaStretchMax = 0;
  const double norm = totalT > 0 ? totalS / totalT : 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!(as[t] > 0)) continue;
    const double stretch = at[t] / as[t] * norm;
    s.areaStretchMin = std::min(s.areaStretchMin, stretch);
    s.areaStretchMax = std::max(s.areaStretchMax, stretch);
  }
  std::size_t owned = 0;
  for (auto o : atlas.texelTriangle) owned += o >= 0;
  s.coverage = double(owned) / double(atlas.texelTriangle.size());
  s.guestAreaFraction = totalS > 0 ? guestArea / totalS : 0;
}

/// Turns each chart to its principal axes, so that long thin charts get tight bounding boxes.
inline void alignChartsToPrincipalAxes(const ChartSet& charts, std::vector<glm::dvec2>& projected) {
  const std::size_t n = std::size_t(charts.count());
  std::vector<glm::dvec2> mean(n, glm::dvec2(0));
  std::vector<double> count(n, 0), sxx(n, 0), sxy(n, 0), syy(n, 0);
  for (std::size_t i = 0; i < projected.size(); ++i) {
    const int c = charts.chartOfTriangle[i / 3];
    if (c < 0) continue;
    mean[std::size_t(c)] += projected[i];
    count[std::size_t(c)] += 1;
  }
  for (std::size_t c = 0; c < n; ++c) mean[c] /= std::max(count[c], 1.0);
  for (std::size_t i = 0; i < projected.size(); ++i) {
    const int c = charts.chartOfTriangle[i / 3];
    if (c < 0) continue;
    const glm::dvec2 d = projected[i] - mean[std::size_t(c)];
    sxx[std::size_t(c)] += d.x * d.x, sxy[std::size_t(c)] += d.x * d.y, syy[std::size_t(c)] += d.y * d.y;
  }
  for (std::size_t i = 0; i < projected.size(); ++i) {
    const int c = charts.chartOfTriangle[i / 3];
    if (c < 0) continue;
    const std::size_t k = std::size_t(c);
    const double angle = 0.5 * std::atan2(2 * sxy[k], sxx[k] - syy[k]);  // major axis -> x (a rotation: keeps CCW)
    const double co = std::cos(angle), si = std::sin(angle);
    const glm::dvec2 d = projected[i] - mean[k];
    projected[i] = {co * d.x + si * d.y, -si * d.x + co * d.y};
  }
}

/// Lays the charts out at `texelsPerMm`; false when they do not fit.
inline bool layoutCharts(const scene::TriangleMesh& mesh, const ChartSet& charts, int gutter, double texelsPerMm,
                         const std::vector<glm::dvec2>& projected, TextureAtlas& atlas) {
  const int n = charts.count();
  std::vector<glm::dvec2> lo(static_cast<std::size_t>(n), glm::dvec2(std::numeric_limits<double>::infinity()));
  std::vector<glm::dvec2> hi(static_cast<std::size_t>(n), glm::dvec2(-std::numeric_limits<double>::infinity()));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const int c = charts.chartOfTriangle[t];
    if (c < 0) continue;
    for (int k = 0; k < 3; ++k) {
      lo[std::size_t(c)] = glm::min(lo[std::size_t(c)], projected[3 * t + k]);
      hi[std::size_t(c)] = glm::max(hi[std::size_t(c)], projected[3 * t + k]);
    }
  }
  std::vector<int> w(static_cast<std::size_t>(n)), h(static_cast<std::size_t>(n));
  for (int c = 0; c < n; ++c) {
    const glm::dvec2 ext = (hi[std::size_t(c)] - lo[std::size_t(c)]) * texelsPerMm;
    w[std::size_t(c)] = int(std::ceil(ext.x)) + 1 + 2 * gutter;
    h[std::size_t(c)] = int(std::ceil(ext.y)) + 1 + 2 * gutter;
  }
  const auto corners = shelfPack(w, h, atlas.resolution);
  if (corners.empty() && n > 0) return false;
  atlas.uv.assign(3 * mesh.triangles.size(), glm::dvec2(0));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const int c = charts.chartOfTriangle[t];
    if (c < 0) continue;
    const glm::dvec2 origin(corners[std::size_t(c)].x + gutter, corners[std::size_t(c)].y + gutter);
    for (int k = 0; k < 3; ++k) atlas.uv[3 * t + k] = origin + (projected[3 * t + k] - lo[std::size_t(c)]) * texelsPerMm;
  }
  return true;
}

}  // namespace detail

/// Built-in parameterization of any triangle mesh (closed or not) into a packed atlas.
inline TextureAtlas buildTextureAtlas(const scene::TriangleMesh& mesh, const AtlasOptions& options = {}) {
  if (options.resolution < 8 || options.resolution > 16384)
    throw std::invalid_argument("atlas resolution must be in [8, 16384], not " + std::to_string(options.resolution));
  if (!(options.maxNormalAngleDeg > 0 && options.maxNormalAngleDeg < 90))
    throw std::invalid_argument("chart cone angle must be in (0, 90) degrees");
  const auto neighbours = triangleNeighbours(mesh);
  std::vector<double> maxAngle(mesh.triangles.size(), options.maxNormalAngleDeg * optics::kPi / 180.0);
  TextureAtlas atlas;
  atlas.resolution = options.resolution;
  for (int round = 0;; ++round) {
    const ChartSet charts = segmentCharts(mesh, maxAngle, neighbours);
    std::vector<glm::dvec2> projected(3 * mesh.triangles.size(), glm::dvec2(0));
    double projectedArea = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const int c = charts.chartOfTriangle[t];
      if (c < 0) continue;
      for (int k = 0; k < 3; ++k)
        projected[3 * t + k] = projectToChart(glm::dvec3(mesh.positions[mesh.triangles[t][k]]), charts.axis[std::size_t(c)]);
      projectedArea += 0.5 * detail::signedArea2(projected[3 * t], projected[3 * t + 1], projected[3 * t + 2]);
    }
    detail::alignChartsToPrincipalAxes(charts, projected);
    // The largest scale at which the charts fit: bisect between a scale that fits and one that cannot
    // (the charts' area alone would exceed the atlas).
    double hi = options.resolution / std::sqrt(std::max(projectedArea, 1e-300));
    double lo = hi;
    for (int i = 0; i < 64 && !detail::layoutCharts(mesh, charts, options.gutter, lo, projected, atlas); ++i) lo *= 0.5;
    if (!detail::layoutCharts(mesh, charts, options.gutter, lo, projected, atlas))
      throw std::invalid_argument("atlas: " + std::to_string(charts.count()) + " charts do not fit into " +
                                  std::to_string(options.resolution) + "^2 texels even with their gutters; raise the atlas resolution");
    for (int i = 0; i < 20; ++i) {
      const double mid = std::sqrt(lo * hi);
      (detail::layoutCharts(mesh, charts, options.gutter, mid, projected, atlas) ? lo : hi) = mid;
    }
    detail::layoutCharts(mesh, charts, options.gutter, lo, projected, atlas);
    atlas.chartOfTriangle = charts.chartOfTriangle;
    atlas.stats = {};
    atlas.stats.charts = charts.count();
    atlas.stats.texelsPerMm = lo;
    atlas.stats.recutRounds = round;
    const std::vector<int> folded = detail::rasterize(mesh, atlas);
    if (folded.empty() || round >= options.maxRecuts) {
      if (!folded.empty())
        throw std::invalid_argument("atlas: " + std::to_string(folded.size()) + " charts still fold after " +
                                    std::to_string(round) + " re-cuts; check the mesh for self-intersections");
      break;
    }
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      if (std::binary_search(folded.begin(), folded.end(), atlas.chartOfTriangle[t])) maxAngle[t] *= 0.5;
  }
  detail::placeGuests(mesh, atlas);
  detail::computeStats(mesh, atlas);
  return atlas;
}

/// An atlas from the mesh's own texture coordinates (3 per triangle, in [0, 1]^2). Overlapping UV
/// islands (mirrored or shared texture) would sum two surfaces' irradiance in one texel: refused.
inline TextureAtlas atlasFromUvs(const scene::TriangleMesh& mesh, const std::vector<glm::dvec2>& cornerUv, int resolution) {
  if (cornerUv.size() != 3 * mesh.triangles.size())
    throw std::invalid_argument("atlas: expected 3 texture coordinates per triangle (" +
                                std::to_string(3 * mesh.triangles.size()) + "), got " + std::to_string(cornerUv.size()));
  TextureAtlas atlas;
  atlas.resolution = resolution;
  atlas.uv.resize(cornerUv.size());
  atlas.chartOfTriangle.assign(mesh.triangles.size(), 0);
  for (std::size_t i = 0; i < cornerUv.size(); ++i) {
    if (!(cornerUv[i].x >= 0 && cornerUv[i].x <= 1 && cornerUv[i].y >= 0 && cornerUv[i].y <= 1))
      throw std::invalid_argument("atlas: texture coordinate " + std::to_string(i) + " lies outside [0, 1]^2; "
                                  "use the built-in parameterization instead");
    atlas.uv[i] = cornerUv[i] * double(resolution);
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (!(mesh.triangleArea(t) > 0)) atlas.chartOfTriangle[t] = -1;
  if (!detail::rasterize(mesh, atlas).empty())
    throw std::invalid_argument("atlas: the mesh's texture coordinates overlap (two triangles share texels); "
                                "use the built-in parameterization instead");
  atlas.stats.charts = 1;
  detail::placeGuests(mesh, atlas);
  detail::computeStats(mesh, atlas);
  return atlas;
}

}  // namespace lucent::atlas
