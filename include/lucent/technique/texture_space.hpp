#pragma once
/// @file texture_space.hpp
/// @brief The techniques of Chang et al. 2008: tsis (Sec. 2-3), hybrid (Sec. 4:
/// local Rd Wl by translucent shadow maps + global Rd Wg by tsis) and tsm (the ring filter over all
/// of Rd). Prepare is the parameterization (once per mesh); a frame is what the paper's run time
/// redoes when light or material change: irradiance into the atlas, sampling, shadow maps,
/// evaluation.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "../atlas/hybrid.hpp"
#include "../atlas/importance_samples.hpp"
#include "../atlas/irradiance_atlas.hpp"
#include "../atlas/texture_atlas.hpp"
#include "../atlas/tsis_evaluator.hpp"
#include "../reference/vertex_radiosity.hpp"
#include "lit_stages.hpp"
#include "single_scattering_term.hpp"
#include "technique.hpp"
#include "validity.hpp"

namespace lucent::technique {

namespace detail {

inline std::vector<KnobSpec> atlasKnobs() {
  return {KnobSpec::integer("atlas-resolution", 1024, 16, 8192, "atlas texels per side",
                            Phase::Prepare),
          KnobSpec::real("chart-angle", "40", 1, 80, "degrees",
                         "chart cone half-angle (smaller: more charts, less distortion)",
                         Phase::Prepare)};
}

inline std::vector<KnobSpec> samplingKnobs(long long samples) {
  return {KnobSpec::integer("samples", samples, 1, 10000000,
                            "importance samples N drawn over the atlas (Eq. 10)"),
          KnobSpec::choice("sampler", {"mip", "row"}, "texel ICDF: mip (Fig. 2b) or row (Fig. 2a)"),
          KnobSpec::choice(
              "pattern", {"stratified", "independent"},
              "2-D input points: stratified (Hammersley, shifted) or independent (as the paper)"),
          KnobSpec::integer("seed", 1, 0, 2147483647, "random seed")};
}

inline std::vector<KnobSpec> ringKnobs() {
  return {
      KnobSpec::integer("rings", 20, 1, 1000, "concentric rings L of the local filter (Sec. 4.2)"),
      KnobSpec::integer("ring-samples", 20, 1, 1000,
                        "samples C per ring (the filter has L*C+1 samples)"),
      KnobSpec::integer("map", 512, 8, 8192,
                        "translucent shadow map resolution (texels per side)")};
}

inline std::vector<KnobSpec> evaluationKnobs() {
  return {KnobSpec::choice(
              "eval", {"pixel", "vertex"},
              "where Eq. 11 is summed: pixel (every shaded point) or vertex (interpolated B)"),
          envStrataKnob("irradiance texel"), profileKnob()};
}

template <class... Lists>
std::vector<KnobSpec> concat(Lists... lists) {
  std::vector<KnobSpec> out;
  (out.insert(out.end(), lists.begin(), lists.end()), ...);
  return out;
}

/// The chart atlas (prepare).
inline atlas::TextureAtlas buildChartAtlas(const SceneDescription& scene, const KnobValues& knobs,
                                           Statistics& stats) {
  atlas::AtlasOptions ao;
  ao.resolution = int(knobs.integer("atlas-resolution"));
  ao.maxNormalAngleDeg = knobs.real("chart-angle");
  atlas::TextureAtlas a = stats.timePrepare("atlas", [&] {
    try {
      return atlas::buildTextureAtlas(scene.mesh, ao);
    } catch (const std::invalid_argument& e) {
      throw RequestError(std::string(e.what()) + " (mesh " + scene.meshName + ")");
    }
  });
  stats.figures["atlas_charts"] = a.stats.charts;
  stats.figures["atlas_coverage"] = a.stats.coverage;
  stats.figures["atlas_stretch_min"] = a.stats.areaStretchMin;
  stats.figures["atlas_stretch_max"] = a.stats.areaStretchMax;
  stats.figures["atlas_guest_area_fraction"] = a.stats.guestAreaFraction;
  stats.figures["atlas_recut_rounds"] = a.stats.recutRounds;
  stats.bytes += double(std::size_t(ao.resolution) * std::size_t(ao.resolution) * sizeof(int));
  return a;
}

/// The chart atlas and the surface under it (prepare): what depends on the mesh only, so a frame
/// redoes only the light.
inline std::shared_ptr<const atlas::AtlasSurface> buildAtlas(const SceneDescription& scene,
                                                             const KnobValues& knobs,
                                                             Statistics& stats) {
  const atlas::TextureAtlas charts = buildChartAtlas(scene, knobs, stats);
  auto surface = stats.timePrepare("atlas_surface", [&] {
    return atlas::buildAtlasSurface(charts, scene.mesh, scene.vertexNormals, scene.parallelFor);
  });
  const std::size_t texels = std::size_t(charts.resolution) * std::size_t(charts.resolution);
  stats.bytes += double(texels * 3 * sizeof(glm::vec3) +
                        surface->owned.size() * (2 * sizeof(glm::vec3) + sizeof(float) + 4));
  return surface;
}

/// Irradiance into the atlas and the N importance samples (a frame's first stages). The atlas is
/// left in `scratch`, whose buffers the next light change refills.
inline atlas::ImportanceSamples drawSamples(
    const std::shared_ptr<const atlas::AtlasSurface>& surface, const SceneDescription& scene,
    const KnobValues& knobs, Statistics& stats, atlas::IrradianceAtlas& scratch) {
  scratch = stats.timeFrame("irradiance", [&] {
    return atlas::lightAtlas(surface, scene.lights, *scene.caster, irradianceSettings(scene, knobs),
                             scene.parallelFor, scene.stage("irradiance atlas"),
                             std::move(scratch));
  });
  const atlas::IrradianceAtlas& irradiance = scratch;
  stats.figures["transmitted_power"] =
      irradiance.totalPower.x + irradiance.totalPower.y + irradiance.totalPower.z;
  scene.checkCancelled();
  atlas::SamplingOptions so;
  so.samples = int(knobs.integer("samples"));
  so.sampler = knobs.pick<atlas::TexelSampler>(
      "sampler", {{"mip", atlas::TexelSampler::Mipmap}, {"row", atlas::TexelSampler::RowMajor}});
  so.pattern = knobs.pick<atlas::SamplePattern>(
      "pattern", {{"stratified", atlas::SamplePattern::Stratified},
                  {"independent", atlas::SamplePattern::Independent}});
  so.seed = std::uint64_t(knobs.integer("seed"));
  auto samples =
      stats.timeFrame("sampling", [&] { return atlas::drawImportanceSamples(irradiance, so); });
  stats.samples = double(samples.size());
  stats.sampleUnit = "importance samples";
  if (samples.size() == 0)
    stats.warnings.push_back("no light reaches the surface: the image is black");
  return samples;
}

/// B at the request's points, summed there (eval=pixel) or at the mesh's vertices and interpolated.
/// B at the vertices depends on the light stages only: it is summed once into `vertexCache` (the
/// light stages' own, LitStages::vertexCache) and a view change only interpolates.
template <class Radiosity>
std::vector<glm::dvec3> evaluate(const Radiosity& eval, const SceneDescription& scene,
                                 const ShadeRequest& request, const KnobValues& knobs,
                                 Statistics& stats, std::vector<glm::dvec3>& vertexCache) {
  const bool perVertex = knobs.pick<bool>("eval", {{"pixel", false}, {"vertex", true}});
  return stats.timeFrame("evaluation", [&] {
    if (!perVertex || request.vertices)
      return radiosityAt(eval, scene, request, "Eq. 11 per point");
    if (vertexCache.size() != scene.mesh.positions.size())
      vertexCache = radiosityAt(eval, scene, vertexRequest(scene.mesh), "Eq. 11 per vertex");
    const std::vector<glm::dvec3>& atVertices = vertexCache;
    std::vector<glm::dvec3> b(request.points.size());
    for (std::size_t i = 0; i < b.size(); ++i)
      b[i] = reference::interpolateAtHit(scene.mesh, atVertices, request.points[i]);
    return b;
  });
}

/// One light-view map per light, `resolution` texels a side, timed as frame phase `phase`.
inline std::vector<atlas::TranslucentShadowMap> lightViewMaps(const SceneDescription& scene,
                                                              const scene::IrradianceSettings& irr,
                                                              int resolution, Statistics& stats,
                                                              const std::string& phase) {
  return stats.timeFrame(phase, [&] {
    std::vector<atlas::TranslucentShadowMap> maps;
    for (const auto& light : scene.lights)
      maps.emplace_back(light, scene.mesh, scene.vertexNormals, *scene.caster, irr, resolution,
                        scene.parallelFor);
    return maps;
  });
}

/// One translucent shadow map per light (hybrid, tsm).
inline std::vector<atlas::TranslucentShadowMap> shadowMaps(const SceneDescription& scene,
                                                           const KnobValues& knobs,
                                                           Statistics& stats) {
  return lightViewMaps(scene, irradianceSettings(scene, knobs), int(knobs.integer("map")), stats,
                       "shadow_map");
}

template <class Profile>
atlas::RingFilter ringFilter(const Profile& profile, const KnobValues& knobs, double diag,
                             Statistics& stats) {
  auto ring =
      atlas::makeRingFilter([&](double r) { return glm::dvec3(profile(float(r))); },
                            int(knobs.integer("rings")), int(knobs.integer("ring-samples")), diag);
  stats.figures["local_filter_samples"] = ring.sampleCount();
  stats.figures["local_filter_radius_mm"] = ring.outerRadius;
  return ring;
}

/// The hybrid's split as a frame builds it (Chang et al. 2008 Sec. 4.1-4.2), shared with its GPU
/// twin: the profile, Rp, the tables of Rd Wl and Rd Wg on [0, diag] and the local ring filter.
struct HybridSplit {
  optics::Profile<double> profile;
  double rp;
  atlas::HybridProfiles tables;
  atlas::RingFilter ring;
  HybridSplit(const optics::Material& material, const KnobValues& knobs, double diag,
              Statistics& stats)
      : profile(profileOf<double>(material, knobs)),
        rp(atlas::hybridRp(profile, knobs.real("c"))),
        tables(profile, rp, diag, knobs.real("K")),
        ring(ringFilter(tables.local, knobs, diag, stats)) {
    stats.figures["rp_mm"] = rp;
  }
};

/// tsis's light stages: irradiance into the atlas, N samples, and the sum over them of the
/// profile's table (or its closed form with rd=exact).
inline atlas::TsisEvaluator tsisEvaluator(const std::shared_ptr<const atlas::AtlasSurface>& atlas,
                                          const SceneDescription& scene, const KnobValues& knobs,
                                          Statistics& stats, atlas::IrradianceAtlas& scratch) {
  atlas::ImportanceSamples samples = drawSamples(atlas, scene, knobs, stats, scratch);
  const auto profile = profileOf<float>(scene.medium.material, knobs);
  const RdLookup lookup = rdLookupOf(knobs);
  if (lookup.closedForm) return atlas::TsisEvaluator(std::move(samples), profile);
  if (!lookup.warning.empty()) stats.warnings.push_back(lookup.warning);
  const auto table = optics::radialTable(profile, float(scene.mesh.bounds().diagonal()));
  stats.figures["rd_table_nodes"] = double(table.size());
  return atlas::TsisEvaluator(std::move(samples), table, profile.eta);
}

class Tsis final : public Prepared {
 public:
  Tsis(const SceneDescription& scene, const KnobValues& knobs, Statistics& stats)
      : Prepared(knobs), mAtlas(buildAtlas(scene, knobs, stats)) {}
  FrameResult frame(const SceneDescription& scene, const ShadeRequest& request,
                    Statistics& stats) override {
    const atlas::TsisEvaluator& eval = mLit.get(scene, mKnobs, stats, [&](Statistics& s) {
      return tsisEvaluator(mAtlas, scene, mKnobs, s, mIrradiance);
    });
    FrameResult out;
    out.radiosity = evaluate(eval, scene, request, mKnobs, stats, mLit.vertexCache());
    out.exitScale = double(profileOf<float>(scene.medium.material, mKnobs).exitScale);
    return out;
  }

 private:
  std::shared_ptr<const atlas::AtlasSurface> mAtlas;
  atlas::IrradianceAtlas mIrradiance;  ///< the last frame's, whose buffers the next one refills
  LitStages<atlas::TsisEvaluator> mLit;
};

class Hybrid final : public Prepared {
 public:
  Hybrid(const SceneDescription& scene, const KnobValues& knobs, Statistics& stats)
      : Prepared(knobs), mAtlas(buildAtlas(scene, knobs, stats)) {}
  FrameResult frame(const SceneDescription& scene, const ShadeRequest& request,
                    Statistics& stats) override {
    const Lit& lit = mLit.get(scene, mKnobs, stats, [&](Statistics& s) { return build(scene, s); });
    FrameResult out;
    out.radiosity = evaluate(atlas::HybridEvaluator(lit.local, lit.global), scene, request, mKnobs,
                             stats, mLit.vertexCache());
    out.exitScale = lit.exitScale;
    return out;
  }

 private:
  /// The light stages: the split, a translucent shadow map per light, the samples.
  struct Lit {
    atlas::LocalTermEvaluator local;
    atlas::TsisEvaluator global;
    double exitScale;
  };
  Lit build(const SceneDescription& scene, Statistics& stats) {
    HybridSplit split(scene.medium.material, mKnobs, scene.mesh.bounds().diagonal(), stats);
    const float eta = float(scene.medium.material.eta);
    atlas::LocalTermEvaluator local(shadowMaps(scene, mKnobs, stats), std::move(split.ring),
                                    split.tables.local, eta);
    atlas::TsisEvaluator global(drawSamples(mAtlas, scene, mKnobs, stats, mIrradiance),
                                split.tables.global, eta);
    return {std::move(local), std::move(global), split.profile.exitScale};
  }

  std::shared_ptr<const atlas::AtlasSurface> mAtlas;
  atlas::IrradianceAtlas mIrradiance;  ///< the last frame's, whose buffers the next one refills
  LitStages<Lit> mLit;
};

class Tsm final : public Prepared {
 public:
  explicit Tsm(const KnobValues& knobs) : Prepared(knobs) {}
  FrameResult frame(const SceneDescription& scene, const ShadeRequest& request,
                    Statistics& stats) override {
    const atlas::LocalTermEvaluator& local =
        mLit.get(scene, mKnobs, stats, [&](Statistics& s) { return build(scene, s); });
    FrameResult out;
    out.radiosity = evaluate(local, scene, request, mKnobs, stats, mLit.vertexCache());
    out.exitScale = profileOf<double>(scene.medium.material, mKnobs).exitScale;
    return out;
  }

 private:
  /// The light stages: the filter of all of Rd and a translucent shadow map per light.
  atlas::LocalTermEvaluator build(const SceneDescription& scene, Statistics& stats) const {
    const auto rd = profileOf<double>(scene.medium.material, mKnobs);
    const double diag = scene.mesh.bounds().diagonal();
    const auto profile = optics::radialTable(rd, float(diag));
    auto ring = ringFilter(profile, mKnobs, diag, stats);
    stats.samples = stats.figures["local_filter_samples"];
    stats.sampleUnit = "ring filter samples";
    return atlas::LocalTermEvaluator(shadowMaps(scene, mKnobs, stats), std::move(ring), profile,
                                     float(scene.medium.material.eta));
  }

  LitStages<atlas::LocalTermEvaluator> mLit;
};

inline Capabilities textureSpaceCapabilities() {
  Capabilities c;
  c.precomputeScaling = "O(triangles + atlas texels)";
  c.frameScaling = "O(atlas texels + points x samples)";
  c.keepsLightStages = true;
  return c;
}

/// The atlas texel, estimated before the atlas exists: the surface over the texels, half of which
/// the shelf packing fills (measured 0.5-0.7 on the built-in shapes).
inline double atlasTexel(const SceneDescription& scene, const KnobValues& knobs) {
  const double side = double(knobs.integer("atlas-resolution"));
  return std::sqrt(surfaceArea(scene.mesh) / (0.5 * side * side));
}
/// The translucent shadow map's texel: its square covers the object's bounding sphere.
inline double mapTexel(const SceneDescription& scene, const KnobValues& knobs) {
  return scene.mesh.bounds().diagonal() / double(knobs.integer("map"));
}

inline std::string atlasInRange(const SceneDescription& scene, const KnobValues& knobs) {
  return validity::resolvesRd(
      atlasTexel(scene, knobs), "the atlas texel", scene.medium.material,
      "raise atlas-resolution (at most 8192), or use reference or jensen-buhler");
}
inline std::string mapInRange(const SceneDescription& scene, const KnobValues& knobs) {
  return validity::resolvesRd(mapTexel(scene, knobs), "the shadow-map texel", scene.medium.material,
                              "raise map, or use reference or jensen-buhler");
}

}  // namespace detail

inline Technique tsisTechnique() {
  Technique t;
  t.name = "tsis";
  t.summary =
      "texture-space importance sampling: N samples drawn over the atlas by irradiance, Eq. 11";
  t.paper =
      "Mertens, Kautz, Bekaert, Van Reeth, Seidel 2003, Chang et al. 2008 Sec. 3, "
      "Eq. 4-11";
  t.knobs =
      detail::concat(detail::samplingKnobs(1600), detail::atlasKnobs(),
                     std::vector<KnobSpec>{KnobSpec::choice(
                         "rd", {"table", "exact"},
                         "Rd lookup: table (1-D texture, Sec. 3) or exact (the truth's kernel)")},
                     detail::evaluationKnobs());
  t.capabilities = detail::textureSpaceCapabilities();
  t.capabilities.gpuTwin = "vtkLucentPass";
  // The pass sums every sample at every pixel (a GPU watchdog stops long loops), and holds the
  // atlas and its position map as RGBA32F textures (8192^2 would be 1 GiB each).
  t.capabilities.gpuTwinKnobs = {
      {"samples", 65536}, {"atlas-resolution", 4096}, {"rd"}, {"profile"}};
  t.defaultSweep = {{"samples", {"400", "1600", "6400"}}};
  t.quickKnobs = {{"samples", "256"}, {"atlas-resolution", "256"}, {"env-strata", "4"}};
  t.model = "dipole";
  t.validRange =
      validity::thickRange() +
      ", with an atlas texel (about sqrt(2 area) / atlas-resolution) of at most 2 widths "
      "of Rd (the shorter of the mean free path and 1/sigma_tr)";
  t.validity = [](const SceneDescription& scene, const KnobValues& knobs) {
    const std::string thick = validity::opticallyThick(scene.mesh, scene.medium.material);
    return thick.empty() ? detail::atlasInRange(scene, knobs) : thick;
  };
  t.prepare = [](const SceneDescription& scene, const KnobValues& knobs, Statistics& stats) {
    return std::make_unique<detail::Tsis>(scene, knobs, stats);
  };
  return withSingleScattering(std::move(t));
}

inline Technique hybridTechnique() {
  Technique t;
  t.name = "hybrid";
  t.summary =
      "hybrid: local Rd Wl by a translucent shadow map ring filter + global Rd Wg by tsis (Sec. 4)";
  t.paper = "Mertens et al. 2003, Chang et al. 2008 Sec. 4, Eq. 12-14";
  t.knobs = detail::concat(
      detail::samplingKnobs(900), detail::atlasKnobs(), detail::ringKnobs(),
      std::vector<KnobSpec>{
          KnobSpec::real("c", "0.05", 0, kUnbounded, "mm^-1",
                         "importance bound c: Rp is where Rd(r) 2 pi r falls to c (Fig. 4)",
                         Phase::Frame, true),
          KnobSpec::real("K", "1.5", 0, kUnbounded, "mm^-1",
                         "steepness of the local/global weights Wl, Wg", Phase::Frame, true)},
      detail::evaluationKnobs());
  t.capabilities = detail::textureSpaceCapabilities();
  t.capabilities.environmentLights = false;  // a translucent shadow map needs a light view
  t.capabilities.gpuTwin = "vtkLucentPass";
  // tsis's bounds, and the local filter's: every pixel reads all L C taps and two map texels each
  // (a GPU watchdog stops long loops); the map is two RGBA32F textures.
  t.capabilities.gpuTwinKnobs = {{"samples", 65536},
                                 {"atlas-resolution", 4096},
                                 {"rings", 64},
                                 {"ring-samples", 64},
                                 {"map", 4096},
                                 {"c"},
                                 {"K"},
                                 {"profile"}};
  t.defaultSweep = {{"samples", {"400", "900", "3600"}}};
  t.quickKnobs = {{"samples", "256"}, {"atlas-resolution", "256"}, {"map", "128"},
                  {"rings", "8"},     {"ring-samples", "8"},       {"env-strata", "4"}};
  t.model = "dipole";
  t.validRange = validity::thickRange() +
                 ", with atlas and shadow-map texels of at most 2 widths of Rd (the shorter of the "
                 "mean free path and 1/sigma_tr)";
  t.validity = [](const SceneDescription& scene, const KnobValues& knobs) {
    std::string why = validity::opticallyThick(scene.mesh, scene.medium.material);
    if (why.empty()) why = detail::atlasInRange(scene, knobs);
    return why.empty() ? detail::mapInRange(scene, knobs) : why;
  };
  t.prepare = [](const SceneDescription& scene, const KnobValues& knobs, Statistics& stats) {
    return std::make_unique<detail::Hybrid>(scene, knobs, stats);
  };
  return withSingleScattering(std::move(t));
}

inline Technique tsmTechnique() {
  Technique t;
  t.name = "tsm";
  t.summary =
      "translucent shadow map: the ring filter over the light's view applied to all of Rd (local "
      "only)";
  t.paper =
      "Dachsbacher, Stamminger 2003, Translucent Shadow Maps; as the local filter of "
      "Chang et al. 2008 Sec. 4.2";
  t.knobs = detail::concat(detail::ringKnobs(), detail::evaluationKnobs());
  t.capabilities = detail::textureSpaceCapabilities();
  t.capabilities.environmentLights = false;
  t.capabilities.multipleScatteringReach = Reach::Local;
  t.capabilities.precomputeScaling = "none";
  t.capabilities.frameScaling = "O(lights x map texels + points x L x C)";
  t.defaultSweep = {{"rings", {"5", "10", "20", "40"}}};
  t.quickKnobs = {{"map", "128"}, {"rings", "8"}, {"ring-samples", "8"}};
  t.model = "dipole";
  t.validRange =
      validity::thickRange() +
      ", with a shadow-map texel (bounding-box diagonal / map) of at most 2 widths of Rd "
      "(the shorter of the mean free path and 1/sigma_tr)";
  t.validity = [](const SceneDescription& scene, const KnobValues& knobs) {
    const std::string thick = validity::opticallyThick(scene.mesh, scene.medium.material);
    return thick.empty() ? detail::mapInRange(scene, knobs) : thick;
  };
  t.prepare = [](const SceneDescription&, const KnobValues& knobs, Statistics&) {
    return std::make_unique<detail::Tsm>(knobs);
  };
  return t;
}

}  // namespace lucent::technique
