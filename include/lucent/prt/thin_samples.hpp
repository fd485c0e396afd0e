#pragma once
/// @file thin_samples.hpp
/// @brief The irradiance samples (Wang et al. 2005, Sec. 3.1) thinned to the spacing asked for. The
/// surface sampler puts at least one sample on every triangle, so a dense scanned or isosurface
/// mesh gets one per triangle however fine the triangles are, and each sample costs 6 cube^2
/// visibility rays. Samples sharing a grid cell of that spacing (and facing the same way) become
/// one: the member nearest their area-weighted centre, carrying their summed area, so the
/// irradiance the diffusion gathers keeps its total.
#include <vector>

#include "../reference/surface_samples.hpp"
#include "../util/grid_clusters.hpp"

namespace lucent::prt {

/// `samples` merged per cell of side `spacing` where the triangles made them more than twice as
/// many as the spacing asks for (area / spacing^2); a mesh the sampler could place at the spacing
/// keeps its samples as they are.
inline reference::SurfaceSamples thinSamples(const reference::SurfaceSamples& samples,
                                             double spacing) {
  double area = 0;
  for (double a : samples.area) area += a;
  if (!(spacing > 0) || double(samples.size()) <= 2 * area / (spacing * spacing)) return samples;
  const util::GridClusters clusters =
      util::gridClusters(samples.position, samples.faceNormal, spacing);
  reference::SurfaceSamples out;
  out.spacing = spacing;
  for (std::uint32_t i : clusters.representatives(samples.position, samples.area)) {
    out.position.push_back(samples.position[i]);
    out.normal.push_back(samples.normal[i]);
    out.faceNormal.push_back(samples.faceNormal[i]);
  }
  out.area.assign(clusters.count, 0.0);
  for (std::size_t i = 0; i < samples.size(); ++i) out.area[clusters.of[i]] += samples.area[i];
  return out;
}

}  // namespace lucent::prt
