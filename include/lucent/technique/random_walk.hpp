#pragma once
/// @file random_walk.hpp
/// @brief Random-walk subsurface scattering as a technique (walk/random_walk.hpp): per pixel or per
/// vertex, progressive (passes until the per-pixel standard error meets `target-error`), with the
/// standard error of every point. The media are the path tracer's (path_tracing.hpp), so the two
/// differ only in how a walk leaves through a refracting boundary.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <string>

#include "../util/sample_mean.hpp"
#include "../walk/random_walk.hpp"
#include "path_tracing.hpp"

namespace lucent::technique {

namespace detail {

/// Where each request point is entered from, and in which direction the eye looks at it.
struct WalkStart {
  glm::dvec3 point, direction;
  std::uint32_t triangle;
};

/// `media`: mediumSceneOf's, whose first body keeps the scene mesh's triangle indices.
inline std::vector<WalkStart> walkStarts(const reference::MediumScene& media,
                                         const ShadeRequest& request) {
  std::vector<WalkStart> out(request.points.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    const reference::ShadingPoint& p = request.points[i];
    // From the barycentrics, in double: a far camera's hit distance carries float error.
    const glm::dvec3 point = reference::surfacePoint(media, {0, p.triangle, p.u, p.v});
    // A vertex is seen head-on (vertexRequest's cosOut = 1).
    glm::dvec3 d = -media.mesh.areaVector(p.triangle);
    if (request.camera) {
      const int width = request.camera->width;
      d = request.camera
              ->primaryRay(double(request.pixels[i] % std::size_t(width)),
                           double(request.pixels[i] / std::size_t(width)))
              .direction;
    }
    out[i] = {point, glm::normalize(d), p.triangle};
  }
  return out;
}

/// Mean over lit points of the per-point relative standard error (luminance).
inline double meanRelativeError(const std::vector<util::SampleMean>& e) {
  double sum = 0;
  std::size_t lit = 0;
  for (const util::SampleMean& p : e) {
    const glm::dvec3 m = p.mean(), s = p.standardError();
    const double lum = (m.x + m.y + m.z) / 3;
    if (lum > 0) sum += (s.x + s.y + s.z) / 3 / lum, ++lit;
  }
  return lit ? sum / double(lit) : 0.0;
}

class RandomWalking final : public Prepared {
 public:
  explicit RandomWalking(const KnobValues& knobs) : Prepared(knobs) {}

  FrameResult frame(const SceneDescription& scene, const ShadeRequest& request,
                    Statistics& stats) override {
    const reference::MediumScene media =
        mediumSceneOf(scene, mKnobs.real("g"), indexMatchedOf(mKnobs));
    // The scene's own caster serves when the object is the only body (the VTK filter offers no
    // factory); inclusions need one over every body.
    std::unique_ptr<scene::RayCaster> ownCaster;
    const scene::RayCaster* caster = scene.inclusions.empty() ? scene.caster : nullptr;
    if (!caster) {
      if (!scene.makeRayCaster)
        throw RequestError(
            "randomwalk: this front end gives no ray caster over the inclusions' "
            "surfaces; render them with the CLI");
      ownCaster = scene.makeRayCaster(media.mesh);
      caster = ownCaster.get();
    }
    walk::RandomWalkSettings s;
    s.maxEvents = std::uint64_t(mKnobs.integer("max-events"));
    s.exit = mKnobs.pick<walk::ExitRule>(
        "exit", {{"fresnel", walk::ExitRule::Fresnel}, {"first", walk::ExitRule::First}});
    s.environmentByLobe = mKnobs.pick<bool>("env-exit", {{"escape", false}, {"lobe", true}});
    s.heroChoice = heroChoiceOf(mKnobs);
    s.rayEpsilon = scene.rayEpsilon();
    const walk::RandomWalk walker(media, *caster, scene.lights, s);
    const std::vector<WalkStart> starts = walkStarts(media, request);
    std::vector<util::SampleMean> est(starts.size());
    walk::RandomWalkStats total;
    int passes = 0;
    const int spp = stats.timeFrame(
        "random_walk", [&] { return progressive(walker, starts, scene, est, total, passes); });
    FrameResult out;
    out.radiance.resize(est.size());
    std::vector<glm::dvec3> error(est.size());
    for (std::size_t i = 0; i < est.size(); ++i)
      out.radiance[i] = est[i].mean(), error[i] = est[i].standardError();
    standardErrorFigures(out.radiance, error, stats);
    out.extras.emplace_back("stderr", std::move(error));
    report(total, spp, passes, s, media, stats);
    return out;
  }

 private:
  /// Passes of walks, doubling (4, 4, 8, 16, ...: progress and a chance to cancel after each),
  /// until every point has `spp` or the mean relative standard error is at most `target-error`
  /// (0 = exactly spp). Pass k of point i draws from its own generator, so images do not depend on
  /// the thread count. Returns the samples each point got; `passes` learns how many passes ran.
  int progressive(const walk::RandomWalk& walker, const std::vector<WalkStart>& starts,
                  const SceneDescription& scene, std::vector<util::SampleMean>& est,
                  walk::RandomWalkStats& total, int& pass) const {
    const int spp = int(mKnobs.integer("spp"));
    const double target = mKnobs.real("target-error");
    const auto seed = std::uint64_t(mKnobs.integer("seed"));
    const util::Progress progress = scene.stage("random walk");
    int done = 0;
    pass = 0;
    while (done < spp) {
      const int count = std::min(spp - done, std::max(4, done));
      runPass(walker, starts, scene, est, total, seed, pass, count);
      done += count, ++pass;
      if (progress) progress(double(done) / spp);
      scene.checkCancelled();
      if (target > 0 && done >= 8 && meanRelativeError(est) <= target) break;
    }
    return done;
  }

  static void runPass(const walk::RandomWalk& walker, const std::vector<WalkStart>& starts,
                      const SceneDescription& scene, std::vector<util::SampleMean>& est,
                      walk::RandomWalkStats& total, std::uint64_t seed, int pass, int count) {
    std::mutex statsMutex;
    scene.parallelFor(starts.size(), [&](std::size_t begin, std::size_t end) {
      walk::RandomWalkStats local;
      for (std::size_t i = begin; i < end; ++i) {
        util::Rng rng((seed * 1000003ULL + i) * 65537ULL + std::uint64_t(pass));
        for (int k = 0; k < count; ++k)
          est[i].add(
              walker.sample(starts[i].point, starts[i].triangle, starts[i].direction, rng, local));
      }
      const std::lock_guard<std::mutex> lock(statsMutex);
      total.add(local);
    });
  }

  static void report(const walk::RandomWalkStats& st, int spp, int passes,
                     const walk::RandomWalkSettings& s, const reference::MediumScene& media,
                     Statistics& stats) {
    stats.samples = double(st.paths.cameraSamples);
    stats.sampleUnit = "walks";
    stats.figures["spp"] = spp;
    stats.figures["passes"] = passes;
    stats.figures["scatter_events"] = double(st.paths.scatterEvents);
    stats.figures["exits"] = double(st.exits);
    stats.figures["internal_reflections"] = double(st.internalReflections);
    stats.figures["roulette_terminations"] = double(st.paths.rouletteTerminations);
    stats.figures["clear_flights"] = double(st.paths.clearFlights);
    stats.figures["leaked_paths"] = double(st.paths.leakedPaths);
    if (media.media[1].eta != media.media[0].eta)
      stats.warnings.push_back(
          std::string("randomwalk: ") +
          (s.exit == walk::ExitRule::First
               ? "every light is gathered where walks first meet the refracting boundary (exit="
                 "first: no internal reflection, no light through other parts of the object)"
           : s.environmentByLobe ? "point, directional and environment light is gathered"
                                 : "point and directional light is gathered") +
          " through a diffuse exit lobe Ft cos / (pi c) instead of along the refracted direction; "
          "low scattering orders are the most affected");
    pathTracerWarnings(st.paths, stats, "randomwalk");
  }
};

}  // namespace detail

inline Technique randomwalkTechnique() {
  Technique t;
  t.name = "randomwalk";
  t.summary =
      "random-walk subsurface scattering (production renderers' method): volumetric walks from "
      "the visible point, light gathered where they leave";
  t.paper =
      "Chiang, Kutz, Burley 2016 (random walk in production); the exit lobe of Habel, "
      "Christensen, Jarosz 2013 Sec. 4; delta tracking and hero-wavelength MIS as the path "
      "tracer";
  t.knobs = {
      detail::sppKnob(),
      KnobSpec::real("target-error", "0", 0, 1, "",
                     "stop adding passes once the mean per-pixel relative standard error "
                     "is at most this (0 = always spp samples)"),
      detail::seedKnob(),
      detail::mediumGKnob(),
      detail::boundaryKnob(),
      KnobSpec::choice("exit", {"fresnel", "first"},
                       "at the refracting boundary: fresnel (reflect back inside or leave "
                       "with the Fresnel probabilities, as the truth) or first (leave at the "
                       "first boundary met and gather every light there, as Cycles)"),
      KnobSpec::choice("env-exit", {"escape", "lobe"},
                       "environment light with exit=fresnel: escape (walks that leave look "
                       "it up along their refracted direction: exact) or lobe (sampled "
                       "through the exit lobe with the map: less noise, the lobe's bias)"),
      detail::heroKnob(),
      detail::maxEventsKnob(),
      detail::stderrKnob()};
  Capabilities& c = t.capabilities;
  c.heterogeneousMedia = c.inclusions = true;
  c.singleScattering = true;
  c.precomputeScaling = "none";
  c.frameScaling = "O(points x spp x scattering events); error ~ 1/sqrt(spp)";
  t.defaultSweep = {{"spp", {"4", "16", "64"}}};
  t.referenceKnobs = {{"spp", "1024"}};
  t.quickKnobs = {{"spp", "4"}};
  t.model = kPhysicalModel;
  t.validRange =
      "any size and medium; behind a refracting boundary point and directional light is gathered "
      "through a diffuse exit lobe, which misplaces the angular shape of the lowest scattering "
      "orders (thin parts, low albedo, strong forward scattering); under an environment alone "
      "(env-exit=escape) and index-matched it is the path tracer";
  t.prepare = [](const SceneDescription&, const KnobValues& knobs, Statistics&) {
    return std::make_unique<detail::RandomWalking>(knobs);
  };
  return t;
}

}  // namespace lucent::technique
