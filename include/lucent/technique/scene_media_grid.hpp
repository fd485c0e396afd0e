#pragma once
/// @file scene_media_grid.hpp
/// @brief A scene's media as a voxel grid (voxel/media_grid.hpp): what the voxel techniques
/// (taulut, voxel-single) discretise.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "../voxel/voxelize.hpp"
#include "knob.hpp"
#include "scene.hpp"
#include "statistics.hpp"
#include "validity.hpp"

namespace lucent::technique::detail {

/// The most voxels a voxel technique's grid may hold: with its surface numbering (4 bytes), density
/// (4) and nearest-surface map (4), 13 bytes each, 1.3 GB. Checked before allocating.
inline constexpr double kMaxGridVoxels = 1e8;

/// The voxel techniques' "voxels" knob help: the bound is on the whole grid, so the largest
/// value that is taken depends on the object's shape.
inline std::string voxelsKnobHelp() {
  return "voxels along the object's longest side (cubic); the grid holds at most " +
         std::to_string(int(kMaxGridVoxels / 1e6)) + " million voxels (about " +
         std::to_string(int(std::cbrt(kMaxGridVoxels))) + " along each side of a cube-shaped "
         "object, more along the longest side of a flat one)";
}

struct VoxelMedia {
  voxel::MediaGrid grid;
  /// With a coefficient field (a scan through a transfer function or a label map): the object's
  /// media, medium 1 + k holding fieldMedia[k]; the inclusions follow. Empty: the object is medium
  /// 1, its material (times the density grid).
  std::vector<Coefficients> fieldMedia;
  bool binned = false;  ///< the field had more distinct values than media fit: binned (stated)
  int objectMedia() const { return fieldMedia.empty() ? 1 : int(fieldMedia.size()); }
};

/// The grid's figures, and a warning when the field was binned.
inline void reportMedia(const VoxelMedia& media, const std::string& technique,
                        const voxel::MediaGrid& grid, Statistics& stats) {
  stats.figures["grid_voxels"] = double(grid.voxelCount());
  stats.figures["field_media"] = double(media.fieldMedia.size());
  if (media.binned)
    stats.warnings.push_back(technique +
                             ": the coefficient field has more distinct values than the " +
                             std::to_string(media.fieldMedia.size()) +
                             " media a voxel's byte holds; binned by mean sigma_t");
}

/// The coefficients of media 1..: the field's as voxelised, the materials' as the scene has them
/// now (a material edit needs no new grid).
inline std::vector<Coefficients> mediaCoefficients(const SceneDescription& scene,
                                                   const std::vector<Coefficients>& fieldMedia) {
  auto of = [](const optics::Material& m) {
    return Coefficients{glm::dvec3(m.sigmaA), glm::dvec3(m.sigmaSPrime)};
  };
  std::vector<Coefficients> out = fieldMedia;
  if (out.empty()) out.push_back(of(scene.medium.material));
  for (const auto& inc : scene.inclusions) out.push_back(of(inc.medium.material));
  return out;
}

namespace media_grid {
inline void checkSize(const SceneDescription& scene, int voxelsAlongLongest) {
  if (scene.inclusions.size() > 254)
    throw RequestError(
        "the voxel techniques take at most 254 inclusions (the grid stores a byte per voxel)");
  for (const auto& inc : scene.inclusions)
    if (inc.medium.coefficients)
      throw RequestError(
          "the voxel techniques take a coefficient field for the object only, not "
          "for an inclusion (" +
          inc.description + ")");
  const glm::ivec3 dims = voxel::gridDimsAround(scene.mesh, voxelsAlongLongest);
  const double count = double(dims.x) * double(dims.y) * double(dims.z);
  if (count > kMaxGridVoxels)
    throw RequestError("voxels=" + std::to_string(voxelsAlongLongest) + " makes a grid of " +
                       std::to_string(dims.x) + " x " + std::to_string(dims.y) + " x " +
                       std::to_string(dims.z) + " voxels, more than the " +
                       std::to_string(int(kMaxGridVoxels / 1e6)) +
                       " million the voxel techniques hold; lower voxels");
}

/// Density fields sampled at the centres of the voxels of their medium (media 1..objectMedia are
/// the object's; a coefficient field already holds the object's density).
inline void sampleDensities(const SceneDescription& scene, int objectMedia,
                            voxel::MediaGrid& grid) {
  grid.density.assign(grid.voxelCount(), 1.f);
  for (int z = 0; z < grid.dims.z; ++z)
    for (int y = 0; y < grid.dims.y; ++y)
      for (int x = 0; x < grid.dims.x; ++x) {
        const std::size_t i = grid.index({x, y, z});
        const std::uint8_t m = grid.medium[i];
        if (m == voxel::kNoMedium) continue;
        const bool object = m <= objectMedia;
        const Medium& medium =
            object ? scene.medium : scene.inclusions[m - objectMedia - 1u].medium;
        if (!medium.density || (object && medium.coefficients)) continue;
        const double d = medium.density(grid.centre({x, y, z}));
        if (!(d >= 0 && std::isfinite(d)))
          throw RequestError("the density of " + medium.densityDescription + " is " +
                             std::to_string(d) +
                             " at a voxel centre; densities must be finite and >= 0");
        grid.density[i] = float(d);
      }
}

/// The object's voxels (medium 1) split into media by the field's value at their centres: one
/// medium per distinct value when they fit, else `slots` bins of equal width in mean sigma_t,
/// each the mean of its voxels.
inline void splitByField(const Medium& medium, int slots, VoxelMedia& out) {
  voxel::MediaGrid& grid = out.grid;
  auto valueAt = [&](std::size_t i, const glm::ivec3& v) {
    const Coefficients c = medium.coefficients(grid.centre(v));
    for (int k = 0; k < 3; ++k)
      if (!(c.sigmaA[k] >= 0 && c.sigmaSPrime[k] >= 0 &&
            std::isfinite(c.sigmaA[k] + c.sigmaSPrime[k])))
        throw RequestError("the coefficient field of " + medium.densityDescription +
                           " gives sigma_a " + valueText(c.sigmaA[k]) + ", sigma_s' " +
                           valueText(c.sigmaSPrime[k]) + " at voxel " + std::to_string(i) +
                           "; coefficients must be finite and >= 0");
    return c;
  };
  using Key = std::tuple<double, double, double, double, double, double>;
  auto key = [](const Coefficients& c) {
    return Key{c.sigmaA.x,      c.sigmaA.y,      c.sigmaA.z,
               c.sigmaSPrime.x, c.sigmaSPrime.y, c.sigmaSPrime.z};
  };
  std::map<Key, int> distinct;
  double lo = 1e300, hi = -1e300;
  auto forObject = [&](auto&& visit) {
    for (int z = 0; z < grid.dims.z; ++z)
      for (int y = 0; y < grid.dims.y; ++y)
        for (int x = 0; x < grid.dims.x; ++x) {
          const std::size_t i = grid.index({x, y, z});
          if (grid.medium[i] == 1) visit(i, valueAt(i, {x, y, z}));
        }
  };
  auto meanSigmaT = [](const Coefficients& c) {
    const glm::dvec3 t = c.sigmaA + c.sigmaSPrime;
    return (t.x + t.y + t.z) / 3;
  };
  forObject([&](std::size_t, const Coefficients& c) {
    if (distinct.size() <= std::size_t(slots)) distinct.emplace(key(c), 0);
    lo = std::min(lo, meanSigmaT(c)), hi = std::max(hi, meanSigmaT(c));
  });
  out.binned = distinct.size() > std::size_t(slots);
  if (!out.binned) {
    for (auto& [k, index] : distinct) {
      index = int(out.fieldMedia.size());
      out.fieldMedia.push_back({{std::get<0>(k), std::get<1>(k), std::get<2>(k)},
                                {std::get<3>(k), std::get<4>(k), std::get<5>(k)}});
    }
    forObject([&](std::size_t i, const Coefficients& c) {
      grid.medium[i] = std::uint8_t(1 + distinct[key(c)]);
    });
    return;
  }
  std::vector<Coefficients> sum(std::size_t(slots), Coefficients{});
  std::vector<double> count(std::size_t(slots), 0);
  auto bin = [&](const Coefficients& c) {
    const double u = hi > lo ? (meanSigmaT(c) - lo) / (hi - lo) : 0.0;
    return std::min(slots - 1, int(u * slots));
  };
  forObject([&](std::size_t i, const Coefficients& c) {
    const int b = bin(c);
    sum[std::size_t(b)].sigmaA += c.sigmaA, sum[std::size_t(b)].sigmaSPrime += c.sigmaSPrime;
    count[std::size_t(b)] += 1;
    grid.medium[i] = std::uint8_t(1 + b);
  });
  for (int b = 0; b < slots; ++b) {
    const double n = std::max(count[std::size_t(b)], 1.0);
    out.fieldMedia.push_back({sum[std::size_t(b)].sigmaA / n, sum[std::size_t(b)].sigmaSPrime / n});
  }
}
}  // namespace media_grid

/// The scene as media: the object is medium 1 (or, with a coefficient field, media 1..K), inclusion
/// i the next (filled after the object, so it wins), a cavity (the mesh's inward shells) none;
/// density fields sampled at the voxel centres.
inline VoxelMedia mediaGridOf(const SceneDescription& scene, int voxelsAlongLongest) {
  media_grid::checkSize(scene, voxelsAlongLongest);
  VoxelMedia out;
  out.grid = voxel::gridAround(scene.mesh, voxelsAlongLongest);
  voxel::fillInside(out.grid, scene.mesh, 1);
  const int inclusions = int(scene.inclusions.size());
  if (scene.medium.coefficients) media_grid::splitByField(scene.medium, 254 - inclusions, out);
  for (int i = 0; i < inclusions; ++i)
    voxel::fillInside(out.grid, scene.inclusions[std::size_t(i)].surface,
                      std::uint8_t(out.objectMedia() + 1 + i));
  bool density = bool(scene.medium.density) && !scene.medium.coefficients;
  for (const auto& inc : scene.inclusions) density |= bool(inc.medium.density);
  if (density) media_grid::sampleDensities(scene, out.objectMedia(), out.grid);
  return out;
}

}  // namespace lucent::technique::detail
