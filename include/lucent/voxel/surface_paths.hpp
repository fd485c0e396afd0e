#pragma once
/// @file surface_paths.hpp
/// @brief Per-medium path lengths between two surface voxels (their centres), three ways that trade
/// memory against time and accuracy:
///  - lut: the paper's table over every pair (path_length_table.hpp): N^2/2 entries, exact;
///  - march: nothing stored, the exact walk per query (grid_traversal.hpp);
///  - hierarchical: surface voxels grouped into clusters of edge^3 voxels; pairs of clusters that
///    touch (Chebyshev distance <= 1 in cluster cells) are walked exactly, the others read the
///    table between the clusters' representatives, scaled by the pair's own distance over the
///    representatives' (the media's shares of the chord kept, its length made exact). Memory falls
///    by about edge^4 (clusters cover the surface, an area).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "path_length_table.hpp"
#include "surface_voxels.hpp"

namespace lucent::voxel {

enum class Storage { Lut, March, Hierarchical };

struct SurfacePathOptions {
  Storage storage = Storage::Lut;
  Precision precision = Precision::Half;
  int clusterEdge = 4;                     ///< hierarchical: voxels per cluster edge
  std::size_t maxTableBytes = 1ull << 30;  ///< refused beyond (checked before allocating)
};

/// Thrown when a table would exceed SurfacePathOptions::maxTableBytes.
class TableTooLarge : public std::length_error {
 public:
  using std::length_error::length_error;
};

class SurfacePaths {
 public:
  /// @param media the number of media (1.. in the grid; 0, none, has no length stored).
  SurfacePaths(MediaGrid grid, const SurfaceVoxels& surface, int media,
               const SurfacePathOptions& options,
               const util::ParallelFor& parallelFor = util::serialFor,
               const util::Progress& progress = {})
      : mGrid(std::move(grid)), mMedia(media), mOptions(options) {
    if (media < 1 || media > 255) throw std::invalid_argument("surface paths: 1..255 media");
    mCentres.reserve(surface.count());
    for (const auto& v : surface.voxels) mCentres.push_back(mGrid.centre(v));
    if (options.storage == Storage::March) return;
    std::vector<glm::dvec3> ends = mCentres;
    if (options.storage == Storage::Hierarchical) ends = cluster(surface);
    const double bytes = PathLengthTable::bytesFor(ends.size(), media, options.precision);
    if (bytes > double(options.maxTableBytes))
      throw TableTooLarge("the optical-thickness table would take " +
                          std::to_string(std::llround(bytes / (1 << 20))) + " MiB (" +
                          std::to_string(ends.size()) + " endpoints, " + std::to_string(media) +
                          " media), over the " + std::to_string(options.maxTableBytes >> 20) +
                          " MiB bound");
    mTable.emplace(mGrid, std::move(ends), media, options.precision, parallelFor, progress);
  }

  /// Path length (mm at density 1) through media 1..media between surface voxels a and b.
  void lengths(std::int32_t a, std::int32_t b, float* out) const {
    if (mOptions.storage == Storage::Lut)
      return mTable->lengths(std::size_t(a), std::size_t(b), out);
    if (mOptions.storage == Storage::Hierarchical) {
      const std::int32_t ca = mClusterOf[std::size_t(a)], cb = mClusterOf[std::size_t(b)];
      const glm::ivec3 gap =
          glm::abs(mClusterCell[std::size_t(ca)] - mClusterCell[std::size_t(cb)]);
      if (std::max({gap.x, gap.y, gap.z}) > 1) {
        mTable->lengths(std::size_t(ca), std::size_t(cb), out);
        const double own = glm::length(mCentres[std::size_t(a)] - mCentres[std::size_t(b)]);
        const double reps =
            glm::length(mTable->point(std::size_t(ca)) - mTable->point(std::size_t(cb)));
        const float scale = float(own / reps);  // reps > 0: clusters two cells apart
        for (int m = 0; m < mMedia; ++m) out[m] *= scale;
        return;
      }
    }
    march(a, b, out);
  }

  /// The exact walk, whatever the storage (the reference the other two are measured against).
  void march(std::int32_t a, std::int32_t b, float* out) const {
    double length[256] = {};
    addPathLengths(mGrid, mCentres[std::size_t(a)], mCentres[std::size_t(b)], mMedia + 1, length);
    for (int m = 0; m < mMedia; ++m) out[m] = float(length[m + 1]);
  }

  std::size_t surfaceVoxels() const { return mCentres.size(); }
  std::size_t tableEndpoints() const { return mTable ? mTable->points() : 0; }
  std::size_t tableBytes() const { return mTable ? mTable->bytes() : 0; }
  int media() const { return mMedia; }
  const MediaGrid& grid() const { return mGrid; }
  const glm::dvec3& centre(std::int32_t i) const { return mCentres[std::size_t(i)]; }

  ///@{ What lengths() reads, for an upload (the GPU twin): the storage, the table (lut: between
  /// surface voxels; hierarchical: between cluster representatives; march: none), and for
  /// hierarchical each surface voxel's cluster and each cluster's cell.
  Storage storage() const { return mOptions.storage; }
  const PathLengthTable* table() const { return mTable ? &*mTable : nullptr; }
  const std::vector<std::int32_t>& clusterOf() const { return mClusterOf; }
  const std::vector<glm::ivec3>& clusterCells() const { return mClusterCell; }
  ///@}

 private:
  /// Groups the surface voxels by cluster cell; returns each cluster's representative centre (the
  /// member nearest the members' mean).
  std::vector<glm::dvec3> cluster(const SurfaceVoxels& surface) {
    if (mOptions.clusterEdge < 1) throw std::invalid_argument("cluster edge must be >= 1");
    std::map<std::tuple<int, int, int>, std::int32_t> id;
    mClusterOf.resize(surface.count());
    std::vector<std::vector<std::size_t>> members;
    for (std::size_t i = 0; i < surface.count(); ++i) {
      const glm::ivec3 cell = surface.voxels[i] / mOptions.clusterEdge;
      const auto key = std::make_tuple(cell.x, cell.y, cell.z);
      auto it = id.find(key);
      if (it == id.end()) {
        it = id.emplace(key, std::int32_t(members.size())).first;
        members.emplace_back();
        mClusterCell.push_back(cell);
      }
      mClusterOf[i] = it->second;
      members[std::size_t(it->second)].push_back(i);
    }
    std::vector<glm::dvec3> reps;
    reps.reserve(members.size());
    for (const auto& group : members) {
      glm::dvec3 mean(0);
      for (std::size_t i : group) mean += mCentres[i];
      mean /= double(group.size());
      std::size_t best = group.front();
      for (std::size_t i : group)
        if (glm::length(mCentres[i] - mean) < glm::length(mCentres[best] - mean)) best = i;
      reps.push_back(mCentres[best]);
    }
    return reps;
  }

  MediaGrid mGrid;
  int mMedia;
  SurfacePathOptions mOptions;
  std::vector<glm::dvec3> mCentres;
  std::optional<PathLengthTable> mTable;
  std::vector<std::int32_t> mClusterOf;  ///< hierarchical: per surface voxel
  std::vector<glm::ivec3> mClusterCell;  ///< hierarchical: per cluster
};

}  // namespace lucent::voxel
