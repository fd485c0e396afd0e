/// The texture-space methods of texture-space-importance-sampling: tsis (Sec. 2-3), hybrid (Sec. 4) and
/// the plain translucent shadow map (tsm, the hybrid's local filter applied to all of Rd).
/// Timing: "precompute" is the parameterization (once per mesh); a "frame" is what the paper's run time
/// redoes when light or material change: irradiance into the atlas, sampling, and evaluation.
#include <chrono>
#include <optional>

#include <lucent/atlas/hybrid.hpp>
#include <lucent/atlas/texture_atlas.hpp>

#include "../util/error.hpp"
#include "../util/progress_bar.hpp"
#include "../util/tbb_parallel.hpp"
#include "methods.hpp"

namespace lucent::render {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

scene::IrradianceSettings irradianceSettings(const cli::Scene& scene, const Knobs& knobs) {
  scene::IrradianceSettings irr;
  irr.eta = scene.material.eta;
  irr.rayEpsilon = 1e-5 * scene.mesh.bounds().diagonal();
  irr.environmentStrata = int(knobs.number("env-strata"));
  return irr;
}

optics::Dipole<double> dipoleOf(const cli::Scene& scene) {
  return optics::Dipole<double>::make(scene.material.sigmaA, scene.material.sigmaSPrime, scene.material.eta);
}

std::vector<KnobSpec> samplingKnobs(const std::string& samples) {
  return {{"samples", samples, "importance samples N drawn over the atlas (Eq. 10)"},
          {"atlas", "1024", "atlas resolution (texels per side)"},
          {"chart-angle", "40", "chart cone half-angle in degrees (smaller: more charts, less distortion)"},
          {"sampler", "mip", "texel ICDF: mip (Fig. 2b) or row (Fig. 2a)"},
          {"pattern", "stratified", "2-D input points: stratified (Hammersley, shifted) or independent (as the paper)"},
          {"seed", "1", "random seed"}};
}

std::vector<KnobSpec> sharedKnobs() {
  return {{"eval", "pixel", "where Eq. 11 is summed: pixel (every shaded point) or vertex (interpolated B)"},
          {"env-strata", "16", "environment light: strata x strata directions per irradiance texel"}};
}

std::vector<KnobSpec> ringKnobs(const std::string& rings, const std::string& perRing) {
  return {{"L", rings, "concentric rings of the local filter (Sec. 4.2)"},
          {"C", perRing, "samples per ring (the filter has L*C+1 samples)"},
          {"map", "512", "translucent shadow map resolution (texels per side)"}};
}

/// The parameterization and the atlas stages shared by tsis and hybrid.
struct AtlasStages {
  atlas::TextureAtlas atlas;
  atlas::ImportanceSamples samples;
};

AtlasStages runAtlasStages(const cli::Scene& scene, const Knobs& knobs, const std::string& method, bool progress,
                           RenderResult& out) {
  AtlasStages s;
  atlas::AtlasOptions ao;
  ao.resolution = knobs.integer("atlas", 16, 8192);
  ao.maxNormalAngleDeg = knobs.number("chart-angle");
  if (!(ao.maxNormalAngleDeg >= 1 && ao.maxNormalAngleDeg <= 80))
    throw InputError("method '" + method + "' knob chart-angle must be in [1, 80] degrees");
  auto t = Clock::now();
  try {
    s.atlas = atlas::buildTextureAtlas(scene.mesh, ao);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string(e.what()) + " (mesh " + scene.meshName + ")");
  }
  out.figures["precompute_seconds"] = since(t);
  out.figures["atlas_charts"] = s.atlas.stats.charts;
  out.figures["atlas_coverage"] = s.atlas.stats.coverage;
  out.figures["atlas_stretch_min"] = s.atlas.stats.areaStretchMin;
  out.figures["atlas_stretch_max"] = s.atlas.stats.areaStretchMax;
  out.figures["atlas_guest_area_fraction"] = s.atlas.stats.guestAreaFraction;
  out.figures["atlas_recut_rounds"] = s.atlas.stats.recutRounds;

  t = Clock::now();
  util::ProgressBar bar("irradiance atlas", progress);
  const auto irradiance = atlas::renderIrradianceAtlas(s.atlas, scene.mesh, scene.vertexNormals, scene.lights,
                                                       *scene.caster, irradianceSettings(scene, knobs), util::tbbFor,
                                                       [&](double f) { bar.update(f); });
  bar.finish();
  out.figures["irradiance_seconds"] = since(t);
  out.figures["transmitted_power"] = irradiance.totalPower.x + irradiance.totalPower.y + irradiance.totalPower.z;

  t = Clock::now();
  atlas::SamplingOptions so;
  so.samples = knobs.integer("samples", 1, 10000000);
  so.sampler = knobs.choice<atlas::TexelSampler>("sampler",
                                           {{"mip", atlas::TexelSampler::Mipmap}, {"row", atlas::TexelSampler::RowMajor}});
  so.pattern = knobs.choice<atlas::SamplePattern>(
      "pattern",
      {{"stratified", atlas::SamplePattern::Stratified}, {"independent", atlas::SamplePattern::Independent}});
  so.seed = std::uint64_t(knobs.number("seed"));
  s.samples = atlas::drawImportanceSamples(irradiance, so);
  out.figures["sampling_seconds"] = since(t);
  out.figures["samples"] = double(s.samples.size());
  if (s.samples.size() == 0) out.notes.push_back("no light reaches the surface: the image is black");
  return s;
}

/// Shades every covered pixel with `eval` (per pixel) or through per-vertex radiosity.
template <class Eval>
void shade(const cli::Scene& scene, const Knobs& knobs, bool progress, const Eval& eval,
           RenderResult& out) {
  const bool perVertex = knobs.choice<bool>("eval", {{"pixel", false}, {"vertex", true}});
  const auto t = Clock::now();
  const auto hits = reference::primaryHits(scene.camera, scene.mesh, scene.vertexNormals, *scene.caster, util::tbbFor);
  std::size_t covered = 0;
  for (const auto& h : hits) covered += h.has_value();
  out.figures["shaded_pixels"] = double(covered);
  util::ProgressBar bar(perVertex ? "Eq. 11 per vertex" : "Eq. 11 per pixel", progress);
  if (perVertex) {
    const atlas::PerVertexShading<Eval> pv(eval, scene.mesh, util::tbbFor, [&](double f) { bar.update(f); });
    out.image = reference::renderTruth(pv, scene.camera, hits, util::tbbFor);
  } else {
    out.image = reference::renderTruth(eval, scene.camera, hits, util::tbbFor, [&](double f) { bar.update(f); });
  }
  bar.finish();
  out.figures["evaluation_seconds"] = since(t);
}

void finish(RenderResult& out, Clock::time_point start) {
  out.seconds = since(start);
  double frame = 0;
  for (const char* k : {"irradiance_seconds", "sampling_seconds", "shadow_map_seconds", "evaluation_seconds"})
    if (out.figures.count(k)) frame += out.figures[k];
  out.figures["frame_seconds"] = frame;
}

/// One translucent shadow map per light, timed.
std::vector<atlas::TranslucentShadowMap> buildShadowMaps(const cli::Scene& scene, const Knobs& knobs,
                                                         const std::string& method, RenderResult& out) {
  const int res = knobs.integer("map", 8, 8192);
  const auto t = Clock::now();
  std::vector<atlas::TranslucentShadowMap> maps;
  for (const auto& light : scene.lights) {
    if (std::holds_alternative<scene::EnvironmentLight>(light))
      throw InputError("method '" + method + "' needs point or directional lights: an environment light has no "
                       "light view for a translucent shadow map; use --method tsis");
    maps.emplace_back(light, scene.mesh, scene.vertexNormals, *scene.caster, irradianceSettings(scene, knobs), res,
                      util::tbbFor);
  }
  out.figures["shadow_map_seconds"] = since(t);
  return maps;
}
}  // namespace

Method tsisMethod() {
  std::vector<KnobSpec> knobs = samplingKnobs("1600");
  knobs.push_back({"rd", "table", "Rd lookup: table (1-D texture, Sec. 3) or exact (the truth's kernel)"});
  for (auto& k : sharedKnobs()) knobs.push_back(k);
  return {"tsis", "texture-space importance sampling: N samples drawn over the atlas by irradiance, Eq. 11", knobs,
          [](const cli::Scene& scene, const Knobs& knobs, bool progress) {
            RenderResult out;
            const auto start = Clock::now();
            AtlasStages s = runAtlasStages(scene, knobs, "tsis", progress, out);
            const bool exact = knobs.choice<bool>("rd", {{"table", false}, {"exact", true}});
            const auto dipoleF = optics::Dipole<float>::make(optics::Rgb<float>(scene.material.sigmaA),
                                                             optics::Rgb<float>(scene.material.sigmaSPrime),
                                                             float(scene.material.eta));
            std::optional<atlas::TsisEvaluator> eval;
            if (exact) {
              eval.emplace(std::move(s.samples), dipoleF);
            } else {
              const optics::RdTable<float> table(dipoleF, float(scene.mesh.bounds().diagonal()));
              out.figures["rd_table_nodes"] = double(table.size());
              eval.emplace(std::move(s.samples), table, float(scene.material.eta));
            }
            shade(scene, knobs, progress, *eval, out);
            finish(out, start);
            return out;
          }};
}

Method hybridMethod() {
  std::vector<KnobSpec> knobs = samplingKnobs("900");
  for (auto& k : ringKnobs("20", "20")) knobs.push_back(k);
  knobs.push_back({"c", "0.05", "importance bound c (mm^-1): Rp is where Rd(r) 2 pi r falls to c (Fig. 4)"});
  knobs.push_back({"K", "1.5", "steepness of the local/global weights Wl, Wg (mm^-1)"});
  for (auto& k : sharedKnobs()) knobs.push_back(k);
  return {"hybrid", "hybrid: local Rd Wl by a translucent shadow map ring filter + global Rd Wg by tsis (Sec. 4)",
          knobs, [](const cli::Scene& scene, const Knobs& knobs, bool progress) {
            RenderResult out;
            const auto start = Clock::now();
            const auto dipole = dipoleOf(scene);
            const double c = knobs.number("c"), k = knobs.number("K");
            if (!(c > 0)) throw InputError("method 'hybrid' knob c must be > 0");
            if (!(k > 0)) throw InputError("method 'hybrid' knob K must be > 0");
            const double diag = scene.mesh.bounds().diagonal();
            const double rp = atlas::hybridRp(dipole, c);
            const atlas::HybridProfiles profiles(dipole, rp, diag, k);
            out.figures["rp_mm"] = rp;
            const int rings = knobs.integer("L", 1, 1000), perRing = knobs.integer("C", 1, 1000);
            auto ring = atlas::makeRingFilter([&](double r) { return glm::dvec3(profiles.local(float(r))); }, rings,
                                              perRing, diag);
            out.figures["local_filter_samples"] = ring.sampleCount();
            out.figures["local_filter_radius_mm"] = ring.outerRadius;
            auto maps = buildShadowMaps(scene, knobs, "hybrid", out);
            const atlas::LocalTermEvaluator local(std::move(maps), std::move(ring), profiles.local, float(scene.material.eta));
            AtlasStages s = runAtlasStages(scene, knobs, "hybrid", progress, out);
            const atlas::TsisEvaluator global(std::move(s.samples), profiles.global, float(scene.material.eta));
            shade(scene, knobs, progress, atlas::HybridEvaluator(local, global), out);
            finish(out, start);
            return out;
          }};
}

Method tsmMethod() {
  std::vector<KnobSpec> knobs = ringKnobs("20", "20");
  for (auto& k : sharedKnobs()) knobs.push_back(k);
  return {"tsm", "translucent shadow map: the ring filter over the light's view applied to all of Rd (local only)",
          knobs, [](const cli::Scene& scene, const Knobs& knobs, bool progress) {
            RenderResult out;
            const auto start = Clock::now();
            const auto dipole = dipoleOf(scene);
            const double diag = scene.mesh.bounds().diagonal();
            const optics::RadialTable<float> profile([&](float r) { return optics::Rgb<float>(dipole.rd(double(r))); },
                                                     float(diag));
            const int rings = knobs.integer("L", 1, 1000), perRing = knobs.integer("C", 1, 1000);
            auto ring = atlas::makeRingFilter([&](double r) { return glm::dvec3(profile(float(r))); }, rings, perRing, diag);
            out.figures["local_filter_samples"] = ring.sampleCount();
            out.figures["local_filter_radius_mm"] = ring.outerRadius;
            auto maps = buildShadowMaps(scene, knobs, "tsm", out);
            const atlas::LocalTermEvaluator local(std::move(maps), std::move(ring), profile, float(scene.material.eta));
            shade(scene, knobs, progress, local, out);
            finish(out, start);
            return out;
          }};
}

}  // namespace lucent::render
