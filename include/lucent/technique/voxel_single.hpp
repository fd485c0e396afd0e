#pragma once
/// @file voxel_single.hpp
/// @brief The "voxel-single" technique: physically normalised single scattering through the same
/// voxel media as the optical-thickness LUT (voxel/single_scattering.hpp); what the LUT's
/// Rd = e^{-tau} stands in for where single scattering dominates.
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "../voxel/single_scattering.hpp"
#include "scene_media_grid.hpp"
#include "technique.hpp"

namespace lucent::technique {

namespace detail {

/// Unreduced coefficients of media 1.. at HG g: sigma_s = sigma_s' / (1 - g), as the path tracer.
inline std::vector<voxel::ScatteringCoefficients> scatteringOf(const SceneDescription& scene,
                                                               double g) {
  auto of = [g](const optics::Material& m) {
    voxel::ScatteringCoefficients c;
    c.sigmaS = glm::dvec3(m.sigmaSPrime) / (1 - g);
    c.sigmaT = glm::dvec3(m.sigmaA) + c.sigmaS;
    return c;
  };
  std::vector<voxel::ScatteringCoefficients> out{of(scene.medium.material)};
  for (const auto& inc : scene.inclusions) out.push_back(of(inc.medium.material));
  return out;
}

class VoxelSingle final : public Prepared {
 public:
  VoxelSingle(const SceneDescription& scene, const KnobValues& knobs, Statistics& stats)
      : mKnobs(knobs),
        mMedia(1 + scene.inclusions.size()),
        mGrid(stats.timePrepare("voxelize",
                                [&] { return mediaGridOf(scene, int(knobs.integer("voxels"))); })) {
    stats.figures["grid_voxels"] = double(mGrid.voxelCount());
    stats.bytes = double(mGrid.voxelCount() * (1 + 4));
  }

  FrameResult frame(const SceneDescription& scene, const ShadeRequest& request,
                    Statistics& stats) override {
    if (1 + scene.inclusions.size() != mMedia)
      throw RequestError(
          "voxel-single: the scene's inclusions changed since prepare; prepare again");
    const double g = mKnobs.real("g");
    const voxel::SingleScatteringEstimator estimator(
        mGrid, scatteringOf(scene, g), scene.lights, scene.mesh, *scene.caster,
        scene.medium.material.eta, g, int(mKnobs.integer("samples")));
    stats.samples = double(mKnobs.integer("samples"));
    stats.sampleUnit = "depths per channel";
    FrameResult out;
    out.radiance.resize(request.points.size());
    const util::Progress progress = scene.stage("single scattering");
    std::atomic<std::size_t> done{0};
    stats.timeFrame("single_scattering", [&] {
      scene.parallelFor(request.points.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
          const auto& p = request.points[i];
          const glm::dvec3 n = scene::shadingNormal(scene.mesh, scene.vertexNormals, p.triangle,
                                                    glm::dvec3(1 - p.u - p.v, p.u, p.v));
          // Seen from the camera, or head-on where there is none (per-vertex requests).
          const glm::dvec3 toEye =
              request.camera ? glm::normalize(request.camera->eye - p.position) : n;
          out.radiance[i] = estimator.radiance(p.position, toEye, n);
        }
        if (progress) progress(double(done += end - begin) / double(request.points.size()));
      });
    });
    return out;
  }

 private:
  KnobValues mKnobs;
  std::size_t mMedia;  ///< media the grid was voxelised with
  voxel::MediaGrid mGrid;
};

}  // namespace detail

inline Technique voxelSingleTechnique() {
  Technique t;
  t.name = "voxel-single";
  t.summary =
      "single scattering through the voxel media: sigma_s p e^{-tau} along the refracted view "
      "ray, tau to the light by the same DDA as taulut";
  t.paper =
      "Jensen, Marschner, Levoy, Hanrahan 2001, A Practical Model for Subsurface Light Transport, "
      "the single-scattering term; sampled at N depths as Wang, Tran, Luebke 2005, over the voxel "
      "media of Mochida et al. 2016";
  t.knobs = {
      KnobSpec::integer("voxels", 60, 2, 1024, "voxels along the object's longest side (cubic)",
                        Phase::Prepare),
      KnobSpec::integer("samples", 16, 1, 4096,
                        "optical depths N sampled along the view ray, per channel"),
      KnobSpec::real("g", "0", -0.99, 0.99, "", "HG mean cosine; sigma_s = sigma_s' / (1 - g)")};
  t.capabilities.environmentLights = false;
  t.capabilities.heterogeneousMedia = true;
  t.capabilities.inclusions = true;
  t.capabilities.singleScattering = true;
  t.capabilities.multipleScattering = false;
  t.capabilities.precomputeScaling = "O(voxels^3) (the grid)";
  t.capabilities.frameScaling = "O(points x 3 N x lights x voxels) DDA steps";
  t.defaultSweep = {{"voxels", {"16", "32", "64", "128"}}};
  t.quickKnobs = {{"voxels", "16"}, {"samples", "4"}};
  t.model = "single scattering";
  t.validRange =
      "any size and medium for the single-scattering term alone (exact at eta 1 up to the "
      "voxelisation; at eta > 1 the light's path is the straight line)";
  t.prepare = [](const SceneDescription& scene, const KnobValues& knobs, Statistics& stats) {
    return std::make_unique<detail::VoxelSingle>(scene, knobs, stats);
  };
  return t;
}

}  // namespace lucent::technique
