#pragma once
/// @file path_tracing.hpp
/// @brief The volumetric path tracer as a technique: the physical truth every dipole technique is
/// measured against. The object becomes one medium (sigma_s = sigma_s' / (1 - g)), with the scene's
/// density field and inclusions; it traces the camera's rays, so it needs a camera.
#include <cmath>
#include <memory>
#include <string>

#include "../reference/volume_path_tracer.hpp"
#include "technique.hpp"

namespace lucent::technique {

namespace detail {

inline reference::Medium pathTracerMedium(const Medium& medium, double g, bool matched) {
  reference::Medium m = reference::mediumFromMaterial(medium.material, g);
  if (matched) m.eta = 1;
  if (medium.coefficients) {
    // sigma_s = sigma_s' / (1 - g) as for the material; the majorant grows with it for g > 0.
    m.coefficients = [field = medium.coefficients, g](const glm::dvec3& x) {
      const Coefficients c = field(x);
      return std::pair<glm::dvec3, glm::dvec3>{c.sigmaA, c.sigmaSPrime / (1 - g)};
    };
    const glm::dvec3 t = medium.maxSigmaT;
    m.maxSigmaT = std::max(t.x, std::max(t.y, t.z)) * std::max(1.0, 1 / (1 - g));
  } else if (medium.density) {
    m.density = medium.density;
    m.maxDensity = 1;
  }
  return m;
}

// The knobs the Monte Carlo techniques (pathtrace, randomwalk) share, each spelt once.
inline KnobSpec sppKnob() {
  return KnobSpec::integer(
      "spp", 16, 1, 1 << 20,
      "samples per pixel (the error falls as 1/sqrt(spp); see the reported standard error)");
}
inline KnobSpec seedKnob() {
  return KnobSpec::integer("seed", 1, 0, 1000000000000000LL,
                           "random seed (fixed seeds give identical images on any thread count)");
}
inline KnobSpec mediumGKnob() {
  return KnobSpec::real(
      "g", "0", -0.99, 0.99, "",
      "HG mean cosine; sigma_s = sigma_s' / (1 - g) keeps the material's reduced coefficient");
}
inline KnobSpec boundaryKnob() {
  return KnobSpec::choice(
      "boundary", {"fresnel", "matched"},
      "fresnel (the material's eta) or matched (eta 1: no refraction, no reflection)");
}
inline KnobSpec heroKnob() {
  return KnobSpec::choice("hero", {"reflectance", "uniform"},
                          "the channel each path draws its distances with: in proportion to the "
                          "medium's total diffuse reflectance per channel, or uniformly");
}
inline KnobSpec maxEventsKnob() {
  return KnobSpec::integer(
      "max-events", static_cast<long long>(reference::PathTracerSettings{}.maxEvents), 10, 1000000000,
      "surface and scattering events per path before it is dropped (counted)");
}
inline KnobSpec stderrKnob() {
  return KnobSpec::outputFile("stderr", ".exr",
                              "write the per-pixel standard error image to this EXR file");
}
inline reference::HeroChoice heroChoiceOf(const KnobValues& knobs) {
  return knobs.pick<reference::HeroChoice>(
      "hero", {{"reflectance", reference::HeroChoice::Reflectance},
               {"uniform", reference::HeroChoice::Uniform}});
}
inline bool indexMatchedOf(const KnobValues& knobs) {
  return knobs.pick<bool>("boundary", {{"fresnel", false}, {"matched", true}});
}

/// The object and its inclusions as the path tracer's media: the object's body first (its
/// triangles keep the scene mesh's indices), each inclusion inside it.
inline reference::MediumScene mediumSceneOf(const SceneDescription& scene, double g,
                                            bool matched) {
  reference::MediumScene media;
  const auto objectId = media.addMedium(pathTracerMedium(scene.medium, g, matched));
  media.addBody(scene.mesh, objectId, 0);
  for (const auto& inclusion : scene.inclusions)
    media.addBody(inclusion.surface,
                  media.addMedium(pathTracerMedium(inclusion.medium, g, matched)), objectId);
  return media;
}

inline reference::PathTracerSettings pathTracerSettings(const SceneDescription& scene,
                                                        const KnobValues& knobs) {
  reference::PathTracerSettings s;
  s.samplesPerPixel = int(knobs.integer("spp"));
  s.seed = std::uint64_t(knobs.integer("seed"));
  s.maxEvents = std::uint64_t(knobs.integer("max-events"));
  s.subsurfaceOnly = knobs.integer("subsurface") == 1;
  s.orders = knobs.pick<reference::ScatteringOrders>(
      "orders", {{"all", reference::ScatteringOrders::All},
                 {"single", reference::ScatteringOrders::Single},
                 {"multiple", reference::ScatteringOrders::Multiple}});
  s.environment = knobs.pick<reference::EnvironmentStrategy>(
      "env", {{"escape", reference::EnvironmentStrategy::Escape},
              {"connect", reference::EnvironmentStrategy::Connect}});
  s.deltaLights = knobs.pick<reference::DeltaLightStrategy>(
      "delta-lights", {{"manifold", reference::DeltaLightStrategy::Manifold},
                       {"joins", reference::DeltaLightStrategy::Joins}});
  s.manifoldGap = int(knobs.integer("manifold-gap"));
  s.heroChoice = heroChoiceOf(knobs);
  s.lightSubpaths = int(knobs.integer("light-paths"));
  s.connectableOnly = knobs.pick<bool>("paths", {{"all", false}, {"connectable", true}});
  s.guideRadius = knobs.real("guide-radius");
  s.rayEpsilon = scene.rayEpsilon();
  return s;
}

/// Standard errors: per pixel (relative, mean over lit pixels) and of the whole image's mean.
inline void standardErrorFigures(const std::vector<glm::dvec3>& mean,
                                 const std::vector<glm::dvec3>& error, Statistics& stats) {
  double relSum = 0, meanSum = 0, varSum = 0;
  std::size_t lit = 0;
  for (std::size_t i = 0; i < mean.size(); ++i) {
    const double lum = (mean[i].x + mean[i].y + mean[i].z) / 3,
                 lumErr = (error[i].x + error[i].y + error[i].z) / 3;
    meanSum += lum;
    varSum += lumErr * lumErr;
    if (lum > 0) relSum += lumErr / lum, ++lit;
  }
  stats.figures["mean_pixel_relative_stderr"] = lit ? relSum / double(lit) : 0;
  stats.figures["image_mean_relative_stderr"] = meanSum > 0 ? std::sqrt(varSum) / meanSum : 0;
}

/// The counts that say something went wrong, as warnings of technique `who`.
inline void pathTracerWarnings(const reference::PathTracerStats& st, Statistics& stats,
                               const std::string& who = "pathtrace") {
  auto warn = [&](std::uint64_t n, const std::string& what) {
    if (n) stats.warnings.push_back(who + ": " + std::to_string(n) + " " + what);
  };
  warn(
      st.truncatedPaths,
      "paths reached max-events and were dropped (their weight is lost: a bias); raise max-events");
  warn(st.leakedPaths, "paths found no surface from inside the medium (is the mesh closed?)");
  warn(st.mediumMismatches,
       "surface crossings disagreed with the media on either side (self-intersecting or nested "
       "wrongly?)");
  warn(st.medium.majorantViolations, "density samples exceeded the majorant and were clamped");
  warn(st.nonFiniteSamples, "non-finite estimates were dropped (please report this)");
}

/// What the manifold searches found, and a warning when some may have missed a refraction point.
inline void manifoldFigures(const reference::ManifoldSearchStats& m, Statistics& stats) {
  stats.figures["manifold_searches"] = double(m.searches);
  stats.figures["manifold_solutions"] = double(m.solutions);
  stats.figures["manifold_no_solution"] = double(m.noSolution);
  stats.figures["manifold_multiple"] = double(m.multiple);
  stats.figures["manifold_capped"] = double(m.capped);
  if (m.capped)
    stats.warnings.push_back("pathtrace: " + std::to_string(m.capped) + " of " +
                             std::to_string(m.searches) +
                             " manifold searches stopped at their cap of facets; refraction points "
                             "beyond were left out");
}

class PathTracing final : public Prepared {
 public:
  explicit PathTracing(const KnobValues& knobs) : Prepared(knobs) {}

  FrameResult frame(const SceneDescription& scene, const ShadeRequest& request,
                    Statistics& stats) override {
    const reference::PathTracerSettings s = pathTracerSettings(scene, mKnobs);
    const double g = mKnobs.real("g");
    const bool matched = indexMatchedOf(mKnobs);
    const reference::MediumScene media = mediumSceneOf(scene, g, matched);
    const auto caster = scene.makeRayCaster(media.mesh);
    const reference::VolumePathTracer tracer(media, *caster, scene.lights, s);
    if (tracer.manifoldDeltaLights())
      stats.warnings.push_back(
          "pathtrace: point/directional light behind a refracting boundary is reached from every "
          "scatter through one refraction by a manifold search (delta-lights=manifold), and by "
          "light subpaths joined to camera segments where it also reflected inside on its way in; "
          "single scattering of that reflected light is left out");
    else if (tracer.joinsDeltaLights())
      stats.warnings.push_back(
          "pathtrace: point/directional light behind a refracting boundary is reached by light "
          "subpaths joined to camera segments (delta-lights=joins); paths whose every "
          "scatter-to-scatter segment is specular (single scattering among them) cannot be sampled "
          "and are left out (delta-lights=manifold includes them)");
    const reference::PathTracedImage img = stats.timeFrame("path_tracing", [&] {
      return reference::renderPathTraced(tracer, *caster, *request.camera, s, scene.parallelFor,
                                         scene.stage("path tracing"));
    });
    FrameResult out;
    std::vector<glm::dvec3> error(request.points.size());
    out.radiance.resize(request.points.size());
    for (std::size_t i = 0; i < request.points.size(); ++i) {
      out.radiance[i] = glm::dvec3(img.image.pixels[request.pixels[i]]);
      error[i] = glm::dvec3(img.standardError.pixels[request.pixels[i]]);
    }
    standardErrorFigures(out.radiance, error, stats);
    out.extras.emplace_back("stderr", std::move(error));
    const reference::PathTracerStats& st = img.stats;
    stats.samples = double(st.cameraSamples);
    stats.sampleUnit = "camera paths";
    stats.figures["spp"] = s.samplesPerPixel;
    stats.figures["camera_samples"] = double(st.cameraSamples);
    stats.figures["scatter_events"] = double(st.scatterEvents);
    stats.figures["light_subpaths"] = double(st.lightSubpaths);
    stats.figures["joins"] = double(st.connections);
    stats.figures["guide_radius_mm"] = tracer.guideRadius();
    stats.figures["truncated_paths"] = double(st.truncatedPaths);
    stats.figures["roulette_terminations"] = double(st.rouletteTerminations);
    stats.figures["clear_flights"] = double(st.clearFlights);
    stats.figures["leaked_paths"] = double(st.leakedPaths);
    if (tracer.manifoldDeltaLights()) manifoldFigures(st.manifold, stats);
    pathTracerWarnings(st, stats);
    return out;
  }
};

}  // namespace detail

inline Technique pathtraceTechnique() {
  Technique t;
  t.name = "pathtrace";
  t.summary =
      "volumetric Monte Carlo path tracing inside the mesh (physical truth: every scattering "
      "order, exact boundary)";
  t.paper =
      "Woodcock delta tracking, hero-wavelength MIS (Wilkie et al. 2014), radiative transfer "
      "equation";
  t.knobs = {
      detail::sppKnob(), detail::seedKnob(), detail::mediumGKnob(), detail::boundaryKnob(),
      KnobSpec::integer(
          "subsurface", 0, 0, 1,
          "1 = leave out the camera's first surface reflection (what the dipole methods render)"),
      KnobSpec::choice("orders", {"all", "single", "multiple"}, "scattering orders counted"),
      KnobSpec::choice(
          "env", {"escape", "connect"},
          "environment light: escape (paths that leave look it up) or connect (light subpaths)"),
      KnobSpec::choice("paths", {"all", "connectable"},
                       "escaping paths counted: all, or connectable (those a delta light could "
                       "reach through a refracting boundary)"),
      KnobSpec::choice("delta-lights", {"manifold", "joins"},
                       "point/directional light behind a refracting boundary: manifold (next-event "
                       "through one refraction from every scatter, Hanika et al. 2015) or joins "
                       "(light subpaths only: noisy, no single scattering)"),
      KnobSpec::integer("manifold-gap", reference::PathTracerSettings{}.manifoldGap, 0, 64,
                        "facets without a refraction point the manifold search crosses looking for "
                        "more (a curved shape focuses light through bands of facets)"),
      detail::heroKnob(),
      KnobSpec::integer(
          "light-paths", 1, 1, 1024,
          "light subpaths per delta light and camera sample (behind a refracting boundary)"),
      KnobSpec::real(
          "guide-radius", "0", 0, 1e9, "mm",
          "spread of light entry points around the camera's (0 = 1/sigma_tr of the material)"),
      detail::maxEventsKnob(), detail::stderrKnob()};
  Capabilities& c = t.capabilities;
  c.heterogeneousMedia = c.inclusions = true;
  c.singleScattering = true;
  c.perVertex = false;
  c.needsCamera = true;
  c.groundTruth = true;
  c.precomputeScaling = "none";
  c.frameScaling = "O(pixels x spp x scattering events); error ~ 1/sqrt(spp)";
  t.defaultSweep = {{"spp", {"4", "16", "64"}}};
  t.referenceKnobs = {{"spp", "1024"}};
  t.quickKnobs = {{"spp", "4"}};
  t.model = kPhysicalModel;
  t.validRange =
      "any size and medium: the error is Monte Carlo noise (reported as the standard error); "
      "behind a refracting boundary a point or directional light is reached through one refraction "
      "by a manifold search over the facets (counted: searches that may have missed a point)";
  t.prepare = [](const SceneDescription&, const KnobValues& knobs, Statistics&) {
    return std::make_unique<detail::PathTracing>(knobs);
  };
  return t;
}

}  // namespace lucent::technique
