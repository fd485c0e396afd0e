#pragma once
/// @file optical_thickness.hpp
/// @brief The voxel optical-thickness LUT technique ("taulut", Mochida et al. 2016): the
/// object and its inclusions voxelised into media, the per-medium path lengths between surface
/// voxels precomputed (or marched, or clustered), and per frame the light views' irradiance and
/// voxel-number maps filtered by Eq. 1-3 (include/lucent/voxel/tau_lut_radiance.hpp).
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "../voxel/surface_paths.hpp"
#include "../voxel/surface_voxel_lookup.hpp"
#include "../voxel/tau_lut_radiance.hpp"
#include "scene_media_grid.hpp"
#include "texture_space.hpp"

namespace lucent::technique {

namespace detail {

/// sigma_t = sigma_a + sigma_s' of media 1.., at frame time.
inline std::vector<glm::dvec3> extinctionOf(const SceneDescription& scene,
                                            const std::vector<Coefficients>& fieldMedia) {
  std::vector<glm::dvec3> out;
  for (const auto& c : mediaCoefficients(scene, fieldMedia))
    out.push_back(c.sigmaA + c.sigmaSPrime);
  return out;
}

inline voxel::SurfacePathOptions surfacePathOptions(const KnobValues& knobs) {
  voxel::SurfacePathOptions o;
  o.storage =
      knobs.pick<voxel::Storage>("storage", {{"lut", voxel::Storage::Lut},
                                             {"march", voxel::Storage::March},
                                             {"hierarchical", voxel::Storage::Hierarchical}});
  o.precision = knobs.pick<voxel::Precision>(
      "precision", {{"fp16", voxel::Precision::Half}, {"fp32", voxel::Precision::Single}});
  o.clusterEdge = int(knobs.integer("cluster"));
  o.maxTableBytes = std::size_t(knobs.integer("max-table-mb")) << 20;
  return o;
}

/// The light-view map must resolve Eq. 3's kernel e^{-sigma_t r}: a texel of at most
/// validity::kMaxStepInRdWidths mean free paths of the object's densest channel, or every tap
/// falls in x_out's own texel, whose first hit lies up to a texel away, and the image goes dark.
inline std::string tauMapInRange(const SceneDescription& scene, const KnobValues& knobs) {
  const double texel = mapTexel(scene, knobs);
  const double mfp = opticalScales(scene.medium.material).shortestMeanFreePath;
  if (!(texel > validity::kMaxStepInRdWidths * mfp)) return "";
  return "the light-view map texel is " + lengthText(texel) + ", more than " +
         std::to_string(int(validity::kMaxStepInRdWidths)) + " mean free paths (" +
         lengthText(mfp) +
         ", the width of e^{-sigma_t r}): the filter's taps fall in one texel "
         "and the image comes out too dark; raise map";
}

class TauLut final : public Prepared {
 public:
  TauLut(const SceneDescription& scene, const KnobValues& knobs, Statistics& stats)
      : Prepared(knobs),
        mMedia(stats.timePrepare("voxelize",
                                 [&] { return mediaGridOf(scene, int(knobs.integer("voxels"))); })),
        mSurface(
            stats.timePrepare("surface_voxels", [&] { return voxel::surfaceVoxels(mMedia.grid); })),
        mPaths(buildPaths(scene, knobs, stats)),
        mLookup(mPaths.grid(), mSurface) {
    reportMedia(mMedia, "taulut", mPaths.grid(), stats);
    stats.figures["surface_voxels"] = double(mSurface.count());
    stats.figures["table_endpoints"] = double(mPaths.tableEndpoints());
    stats.figures["table_bytes"] = double(mPaths.tableBytes());
    stats.bytes = double(mPaths.tableBytes() + mPaths.grid().voxelCount() * (1 + 4 + 4));
  }

  FrameResult frame(const SceneDescription& scene, const ShadeRequest& request,
                    Statistics& stats) override {
    mLookup.resetFarPoints();
    const voxel::TauLutRadiance& model =
        mLit.get(scene, mKnobs, stats, [&](Statistics& s) { return lightStages(scene, s); });
    FrameResult out;
    out.radiosity = evaluate(model, scene, request, mKnobs, stats, mLit.vertexCache());
    stats.figures["far_points"] = double(mLookup.farPoints());
    if (mLookup.farPoints() > 0)
      stats.warnings.push_back(
          "taulut: " + std::to_string(mLookup.farPoints()) + " points lie more than " +
          std::to_string(voxel::SurfaceVoxelLookup::kSearchRadius) +
          " voxels from every surface voxel (features thinner than a voxel); raise voxels");
    return out;
  }

  /// The light stages, kept while the light, the material and the knobs hold (LitStages): the
  /// irradiance map of Eq. 2 per light with its first hits, then the voxel-number map.
  voxel::TauLutRadiance lightStages(const SceneDescription& scene, Statistics& stats) {
    const std::vector<glm::dvec3> sigmaT = extinction(scene);
    std::vector<atlas::TranslucentShadowMap> maps =
        lightViewMaps(scene, irradianceSettings(scene), mapResolution(), stats, "irradiance_maps");
    voxel::TauLutRadiance model = stats.timeFrame("voxel_number_maps", [&] {
      voxel::TauLutRadiance m(std::move(maps), mPaths, mLookup, sigmaT, filterExtinction(sigmaT),
                              taps(), scene.mesh.bounds().diagonal(), scene.parallelFor);
      m.setRotatedPattern(rotatedPattern());
      return m;
    });
    stats.samples = double(taps());
    stats.sampleUnit = "filter taps";
    stats.figures["filter_radius_mm"] = model.filter().outerRadius;
    return model;
  }

  ///@{ What a frame reads, for the CPU frame and the GPU twin alike (vtkLucentPass).
  /// sigma_t of media 1.. under the scene's material now; throws when the media changed.
  std::vector<glm::dvec3> extinction(const SceneDescription& scene) const {
    std::vector<glm::dvec3> sigmaT = extinctionOf(scene, mMedia.fieldMedia);
    if (sigmaT.size() != std::size_t(mPaths.media()))
      throw RequestError("taulut: the scene's media changed since prepare (" +
                         std::to_string(sigmaT.size()) + " now, " + std::to_string(mPaths.media()) +
                         " then); prepare again");
    return sigmaT;
  }
  /// The extinction whose kernel places the taps: the object's densest medium (at density 1), one
  /// filter for every point.
  glm::dvec3 filterExtinction(const std::vector<glm::dvec3>& sigmaT) const {
    glm::dvec3 sigma(0);
    for (int k = 0; k < mMedia.objectMedia(); ++k) sigma = glm::max(sigma, sigmaT[std::size_t(k)]);
    return sigma;
  }
  int taps() const { return 1 + voxel::kTapsPerRing * int(mKnobs.integer("rings")); }
  bool rotatedPattern() const {
    return mKnobs.pick<bool>("pattern", {{"rotated", true}, {"fixed", false}});
  }
  int mapResolution() const { return int(mKnobs.integer("map")); }
  const voxel::SurfacePaths& paths() const { return mPaths; }
  const voxel::SurfaceVoxels& surface() const { return mSurface; }
  const voxel::SurfaceVoxelLookup& lookup() const { return mLookup; }
  ///@}

 private:
  /// The paths between surface voxels; the grid moves into them (mMedia.grid is empty afterwards).
  voxel::SurfacePaths buildPaths(const SceneDescription& scene, const KnobValues& knobs,
                                 Statistics& stats) {
    if (mSurface.count() == 0)
      throw RequestError("taulut: no voxel centre lies inside mesh " + scene.meshName + " at " +
                         std::to_string(knobs.integer("voxels")) +
                         " voxels along its longest side; raise voxels");
    return stats.timePrepare("optical_thickness", [&] {
      try {
        return voxel::SurfacePaths(
            std::move(mMedia.grid), mSurface, mMedia.objectMedia() + int(scene.inclusions.size()),
            surfacePathOptions(knobs), scene.parallelFor, scene.stage("optical-thickness table"));
      } catch (const voxel::TableTooLarge& e) {
        throw RequestError("taulut: " + std::string(e.what()) +
                           "; use storage=hierarchical or storage=march, lower voxels, or raise "
                           "max-table-mb");
      }
    });
  }

  VoxelMedia mMedia;  ///< its grid moves into mPaths (buildPaths)
  voxel::SurfaceVoxels mSurface;
  voxel::SurfacePaths mPaths;
  voxel::SurfaceVoxelLookup mLookup;
  LitStages<voxel::TauLutRadiance> mLit;  ///< after what its model refers to
};

}  // namespace detail

inline Technique taulutTechnique() {
  Technique t;
  t.name = "taulut";
  t.summary =
      "voxel optical-thickness LUT: Rd = e^{-tau} between surface voxels through inner media and "
      "cavities, filtered over the light's view";
  t.paper =
      "Mochida, Okamoto, Kubo, Morishima 2016, Real-time Rendering of Heterogeneous Translucent "
      "Objects using Voxel Number Map (Eurographics posters), Eq. 1-4; the 21-tap filter of "
      "Dachsbacher, Stamminger 2003, Translucent Shadow Maps";
  t.knobs = {
      KnobSpec::integer("voxels", 25, 2, 1024, detail::voxelsKnobHelp(),
                        Phase::Prepare),
      KnobSpec::choice("storage", {"lut", "march", "hierarchical"},
                       "path lengths between surface voxels: the full table, walked per query, or "
                       "a table between clusters with exact walks between neighbours",
                       Phase::Prepare),
      KnobSpec::choice("precision", {"fp16", "fp32"},
                       "table entries: fp16 (2^-11 relative) or fp32", Phase::Prepare),
      KnobSpec::integer("cluster", 4, 2, 64, "hierarchical: voxels per cluster edge",
                        Phase::Prepare),
      KnobSpec::integer("max-table-mb", 1024, 1, 1 << 20,
                        "refuse a table larger than this before building it", Phase::Prepare,
                        "MiB"),
      KnobSpec::integer("rings", 4, 1, 1000,
                        "rings of 5 taps around the centre tap (4: the 21 taps of translucent "
                        "shadow maps)"),
      KnobSpec::choice("pattern", {"rotated", "fixed"},
                       "taps: turned by a per-point angle (noise) or the same for every point "
                       "(the paper's fixed pattern: structured blotches)"),
      KnobSpec::integer("map", 512, 8, 8192,
                        "irradiance and voxel-number map resolution (texels per side)"),
      KnobSpec::choice("eval", {"pixel", "vertex"},
                       "where Eq. 1 is summed: pixel (every shaded point) or vertex "
                       "(interpolated B)")};
  t.capabilities.environmentLights = false;
  t.capabilities.heterogeneousMedia = true;
  t.capabilities.inclusions = true;
  t.capabilities.singleScattering = true;
  t.capabilities.multipleScattering = false;
  t.capabilities.gpuTwin = "vtkLucentPass";
  t.capabilities.keepsLightStages = true;
  // The pass prepares on the CPU and uploads the grid and table as textures; its per-pixel loop
  // holds at most 16 rings (shaders/taulut_shade.frag) and its maps are RGBA32F (4096^2: 256 MiB).
  t.capabilities.gpuTwinKnobs = {{"voxels", 1024}, {"storage"},   {"precision"}, {"cluster", 64},
                                 {"max-table-mb"}, {"rings", 16}, {"pattern"},   {"map", 4096}};
  t.capabilities.precomputeScaling =
      "lut: N_s^2 / 2 walks of O(voxels) (N_s surface voxels); hierarchical: about "
      "(N_s / cluster^2)^2 / 2; march: none";
  t.capabilities.frameScaling = "O(lights x map^2 + points x taps), x O(voxels) for march";
  t.defaultSweep = {{"voxels", {"16", "25", "40", "60"}}};
  t.quickKnobs = {{"voxels", "12"}, {"map", "128"}};
  t.model = "transmittance";
  t.validRange =
      "any size and albedo (an empirical transmittance model: it ignores in-scattering and "
      "albedo; docs/accuracy/taulut.md measures where it holds), with features of at least a "
      "voxel and a light-view map texel (bounding-box diagonal / map) of at most 2 mean free "
      "paths";
  t.validity = detail::tauMapInRange;
  t.prepare = [](const SceneDescription& scene, const KnobValues& knobs, Statistics& stats) {
    return std::make_unique<detail::TauLut>(scene, knobs, stats);
  };
  return t;
}

}  // namespace lucent::technique
