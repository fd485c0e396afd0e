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
inline std::vector<voxel::ScatteringCoefficients> scatteringOf(
    const SceneDescription& scene, const std::vector<Coefficients>& fieldMedia, double g) {
  std::vector<voxel::ScatteringCoefficients> out;
  for (const auto& m : mediaCoefficients(scene, fieldMedia)) {
    voxel::ScatteringCoefficients c;
    c.sigmaS = m.sigmaSPrime / (1 - g);
    c.sigmaT = m.sigmaA + c.sigmaS;
    out.push_back(c);
  }
  return out;
}

class VoxelSingle final : public Prepared {
 public:
  VoxelSingle(const SceneDescription& scene, const KnobValues& knobs, Statistics& stats)
      : Prepared(knobs),
        mInclusions(scene.inclusions.size()),
        mMedia(stats.timePrepare(
            "voxelize", [&] { return mediaGridOf(scene, int(knobs.integer("voxels"))); })) {
    reportMedia(mMedia, "voxel-single", mMedia.grid, stats);
    stats.bytes = double(mMedia.grid.voxelCount() * (1 + 4));
  }

  FrameResult frame(const SceneDescription& scene, const ShadeRequest& request,
                    Statistics& stats) override {
    if (scene.inclusions.size() != mInclusions)
      throw RequestError(
          "voxel-single: the scene's inclusions changed since prepare; prepare again");
    const double g = mKnobs.real("g");
    const voxel::SingleScatteringEstimator estimator(
        mMedia.grid, scatteringOf(scene, mMedia.fieldMedia, g), scene.lights, scene.mesh,
        *scene.caster, scene.medium.material.eta, g, int(mKnobs.integer("samples")));
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
  std::size_t mInclusions;  ///< inclusions the grid was voxelised with
  VoxelMedia mMedia;
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
      KnobSpec::integer("voxels", 60, 2, 1024, detail::voxelsKnobHelp(),
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
