// The random walk (walk/random_walk.hpp) against independent references: radiance invariance (a
// white furnace), Chandrasekhar's half-space, and the volumetric path tracer where the two must
// agree (an index-matched boundary; a refracting one under uniform light, where the exit lobe
// integrates a constant exactly).
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <string>

#include <lucent/scene/shapes.hpp>
#include <lucent/walk/random_walk.hpp>

#include "../unit/chandrasekhar_h.hpp"
#include "path_trace_estimate.hpp"
#include "raycast/embree_ray_caster.hpp"
#include "util/tbb_parallel.hpp"

using namespace lucent;

namespace {
using namespace lucent::test;

/// Mean of n walks started where the rays rayOf(i) meet the scene (rays that miss count 0); each
/// walk's value is divided by weightOf(start) (1 unless given).
Estimate walkEstimate(const walk::RandomWalk& walker, const reference::MediumScene& scene,
                      const scene::RayCaster& caster, std::size_t n,
                      const std::function<scene::Ray(std::size_t, util::Rng&)>& rayOf,
                      std::uint64_t seed,
                      const std::function<double(double cosView)>& weightOf = {}) {
  constexpr std::size_t kBlocks = 64;
  std::vector<glm::dvec3> sum(kBlocks, glm::dvec3(0)), sumSq(kBlocks, glm::dvec3(0));
  std::vector<walk::RandomWalkStats> stats(kBlocks);
  util::tbbFor(kBlocks, [&](std::size_t b0, std::size_t b1) {
    for (std::size_t b = b0; b < b1; ++b)
      for (std::size_t i = b; i < n; i += kBlocks) {
        // Streams apart from path_trace_estimate.hpp's (seed * 7919 + i) and from other seeds'
        // here: shared streams would correlate the estimates a test compares.
        util::Rng rng((seed + 1000) * 1000003ULL + i);
        const scene::Ray r = rayOf(i, rng);
        const auto hit = caster.intersect(r.origin, r.direction, 0, 1e30);
        if (!hit) continue;
        const glm::dvec3 point = reference::surfacePoint(scene, *hit);
        glm::dvec3 l = walker.sample(point, hit->triangle, r.direction, rng, stats[b]);
        if (weightOf) {
          const glm::dvec3 nrm = glm::normalize(scene.mesh.areaVector(hit->triangle));
          l /= weightOf(std::abs(glm::dot(nrm, r.direction)));
        }
        sum[b] += l, sumSq[b] += l * l;
      }
  });
  Estimate e;
  glm::dvec3 s(0), s2(0);
  walk::RandomWalkStats all;
  for (std::size_t b = 0; b < kBlocks; ++b) s += sum[b], s2 += sumSq[b], all.add(stats[b]);
  e.stats = all.paths;
  e.mean = s / double(n);
  e.stdError = glm::sqrt(glm::max(glm::dvec3(0), s2 / double(n) - e.mean * e.mean) / double(n - 1));
  return e;
}

void checkWalkWithin(const Estimate& e, const glm::dvec3& exact, const std::string& what) {
  for (int c = 0; c < 3; ++c) {
    INFO(what << " channel " << c << ": " << e.mean[c] << " +- " << e.stdError[c] << ", exact "
              << exact[c]);
    CHECK(std::abs(e.mean[c] - exact[c]) <= 4 * e.stdError[c] + 1e-12);
  }
}

walk::RandomWalkSettings walkSettings(walk::ExitRule exit, bool environmentByLobe = false) {
  walk::RandomWalkSettings s;
  s.exit = exit;
  s.environmentByLobe = environmentByLobe;
  s.rayEpsilon = 1e-6;
  return s;
}
}  // namespace

TEST_CASE("Random walk white furnace: a non-absorbing Fresnel sphere returns the light it let in") {
  // Under L = 1 from everywhere, with no absorption every walk leaves with the weight Ft(view) it
  // entered with, escaping to L = 1 or gathering it through the exit lobe (which integrates the
  // constant to 1): each walk / Ft has mean 1, for either exit rule and either way of finding the
  // environment, however the channels' sigma_s differ (hero-channel MIS).
  const double R = 1.0, eta = 1.3;
  reference::MediumScene scene;
  scene.addBody(scene::shapes::sphere(R, 4),
                scene.addMedium(medium(glm::dvec3(0), {1, 2, 4}, eta, 0.5)), 0);
  const raycast::EmbreeRayCaster caster(scene.mesh);
  const std::vector<scene::Light> lights{uniformEnvironment(1.0)};
  auto ft = [&](double cosView) { return 1 - optics::fresnelReflectance(cosView, eta); };
  for (int variant = 0; variant < 3; ++variant) {
    const auto exit = variant == 2 ? walk::ExitRule::First : walk::ExitRule::Fresnel;
    const walk::RandomWalk walker(scene, caster, lights, walkSettings(exit, variant == 1));
    std::size_t n = 20000;
    const Estimate e = walkEstimate(
        walker, scene, caster, n,
        [&](std::size_t, util::Rng& rng) { return rayThroughSphere(0.98 * R, rng); }, 1, ft);
    checkWalkWithin(e, glm::dvec3(1),
                    variant == 0   ? "fresnel, escape"
                    : variant == 1 ? "fresnel, lobe"
                                   : "first");
    for (int c = 0; c < 3; ++c) CHECK(e.stdError[c] < 0.01);
    checkClean(e.stats);
  }
}

TEST_CASE(
    "Random walk, index-matched half-space: reflected radiance = (a E / 4pi) H(mu) H(1) / (1 + "
    "mu)") {
  // Index-matched nothing is approximated: delta lights by next-event estimation from each scatter.
  const glm::dvec3 albedo(0.95, 0.8, 0.5);
  reference::MediumScene scene;
  scene.addBody(scene::shapes::box(glm::dvec3(200, 200, 100), 100.0),
                scene.addMedium(medium(glm::dvec3(1) - albedo, albedo, 1.0)), 0);
  for (auto& p : scene.mesh.positions) p.z -= 100;  // top face at z = 0
  const raycast::EmbreeRayCaster caster(scene.mesh);
  const std::vector<scene::Light> lights{
      scene::DirectionalLight{glm::dvec3(0, 0, 1), glm::dvec3(1.0)}};
  const walk::RandomWalk walker(scene, caster, lights, walkSettings(walk::ExitRule::Fresnel));
  for (double mu : {1.0, 0.5}) {
    const test::HalfSpaceView view = test::halfSpaceView(mu, albedo);
    const glm::dvec3& exact = view.exact;
    auto rayOf = [&](std::size_t, util::Rng& rng) { return view.rayAt(rng); };
    const Estimate e = walkEstimate(walker, scene, caster, 20000, rayOf, 3);
    checkWalkWithin(e, exact, "mu " + std::to_string(mu));
    for (int c = 0; c < 3; ++c) CHECK(e.stdError[c] < 0.03 * exact[c]);
    checkClean(e.stats);
  }
}

TEST_CASE(
    "Random walk against the path tracer: index-matched with a density field, an inclusion and a "
    "point light, and behind a Fresnel boundary under uniform light") {
  const double R = 1.0;
  reference::PathTracerSettings pt;
  pt.subsurfaceOnly = true;
  pt.rayEpsilon = 1e-6;
  auto rays = [&](std::size_t, util::Rng& rng) { return rayThroughSphere(0.98 * R, rng); };
  SUBCASE("index-matched: the two estimators agree") {
    reference::MediumScene scene;
    reference::Medium outer = medium({0.3, 0.6, 1.2}, {3, 2, 1.5}, 1.0);
    outer.density = [](const glm::dvec3& p) { return 0.6 + 0.4 * std::sin(4 * p.x) * p.y; };
    const auto outerId = scene.addMedium(outer);
    scene.addBody(scene::shapes::sphere(R, 4), outerId, 0);
    scene.addBody(scene::shapes::sphere(0.4, 3), scene.addMedium(medium({2, 2, 2}, {4, 4, 4}, 1.0)),
                  outerId);
    const raycast::EmbreeRayCaster caster(scene.mesh);
    const std::vector<scene::Light> lights{
        scene::PointLight{glm::dvec3(1.5, 2.5, 2.0), glm::dvec3(6.0)}, uniformEnvironment(0.3)};
    const walk::RandomWalk walker(scene, caster, lights, walkSettings(walk::ExitRule::Fresnel));
    const reference::VolumePathTracer tracer(scene, caster, lights, pt);
    const Estimate w = walkEstimate(walker, scene, caster, 40000, rays, 5);
    const Estimate p = estimate(tracer, 40000, rays, 6);
    checkAgree(w, p, 0.03, "random walk vs path tracer");
    checkClean(w.stats);
  }
  SUBCASE("eta 1.4, absorbing, uniform light: exit=fresnel is exact, exit=first too bright") {
    // Under L from everywhere the lobe gathers exactly L, so exit=fresnel differs from the truth
    // in nothing; leaving at the first boundary skips the internal reflections, in which the truth
    // loses more light to absorption.
    reference::MediumScene scene;
    scene.addBody(scene::shapes::sphere(R, 4),
                  scene.addMedium(medium({0.2, 0.5, 1.0}, {4, 3, 2}, 1.4, 0.3)), 0);
    const raycast::EmbreeRayCaster caster(scene.mesh);
    const std::vector<scene::Light> lights{uniformEnvironment(1.0)};
    const reference::VolumePathTracer tracer(scene, caster, lights, pt);
    const Estimate p = estimate(tracer, 40000, rays, 8);
    const walk::RandomWalk fresnel(scene, caster, lights, walkSettings(walk::ExitRule::Fresnel));
    const Estimate w = walkEstimate(fresnel, scene, caster, 40000, rays, 9);
    checkAgree(w, p, 0.02, "exit=fresnel vs path tracer");
    const walk::RandomWalk first(scene, caster, lights, walkSettings(walk::ExitRule::First));
    const Estimate f = walkEstimate(first, scene, caster, 40000, rays, 10);
    for (int c = 0; c < 3; ++c) {
      INFO("channel " << c << ": first " << f.mean[c] << " truth " << p.mean[c]);
      CHECK(f.mean[c] > p.mean[c] + 4 * std::hypot(f.stdError[c], p.stdError[c]));
    }
    checkClean(w.stats);
  }
}

TEST_CASE("The exit lobe gathers a non-uniform environment as quadrature does, for every layout") {
  // int L(w) Ft(w) cos(w) / (pi c) dw by a fine quadrature over each texel, against the mean of
  // gather(): map and lobe samples weighed by the balance heuristic (nothing occludes: the only
  // surface lies far behind the point).
  reference::MediumScene scene;
  scene.addBody(scene::shapes::sphere(0.1, 2), scene.addMedium(medium({1, 1, 1}, {1, 1, 1}, 1.3)),
                0);
  for (auto& p : scene.mesh.positions) p.z -= 50;
  const raycast::EmbreeRayCaster caster(scene.mesh);
  scene::EnvironmentLight env;
  env.width = 32, env.height = 16;
  for (int row = 0; row < env.height; ++row)
    for (int col = 0; col < env.width; ++col) {
      const bool sun = row == 4 && col == 9;  // a small bright patch, as a real probe's sun
      env.radiance.push_back(sun ? glm::vec3(400, 300, 200)
                                 : glm::vec3(0.2f + 0.1f * float(row), 0.5f, float(col % 3)));
    }
  const walk::ExitLighting exit({env}, caster, 1.3);
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, 0.8, 0.5));
  glm::dvec3 quadrature(0);
  const int sub = 24;
  for (int row = 0; row < env.height; ++row)
    for (int col = 0; col < env.width; ++col)
      for (int a = 0; a < sub; ++a)
        for (int b = 0; b < sub; ++b) {
          const double cos0 = std::cos(optics::kPi * (row + a / double(sub)) / env.height);
          const double cos1 = std::cos(optics::kPi * (row + (a + 1) / double(sub)) / env.height);
          const double cosTheta = 0.5 * (cos0 + cos1),
                       sinTheta = std::sqrt(1 - cosTheta * cosTheta);
          const double phi = 2 * optics::kPi * (col + (b + 0.5) / sub) / env.width;
          const glm::dvec3 d(sinTheta * std::sin(phi), cosTheta, -sinTheta * std::cos(phi));
          const double solidAngle = (cos0 - cos1) * 2 * optics::kPi / (env.width * sub);
          quadrature += env.lookup(d) * exit.lobe(glm::dot(n, d)) * solidAngle;
        }
  util::Rng rng(17);
  glm::dvec3 sum(0), sumSq(0);
  const int count = 200000;
  for (int i = 0; i < count; ++i) {
    const glm::dvec3 g = exit.gather(glm::dvec3(0), n, rng);
    sum += g, sumSq += g * g;
  }
  const glm::dvec3 mean = sum / double(count);
  const glm::dvec3 se = glm::sqrt((sumSq / double(count) - mean * mean) / double(count - 1));
  for (int c = 0; c < 3; ++c) {
    INFO("channel " << c << ": " << mean[c] << " +- " << se[c] << ", quadrature " << quadrature[c]);
    CHECK(std::abs(mean[c] - quadrature[c]) <= 4 * se[c] + 1e-3 * quadrature[c]);
    CHECK(se[c] < 0.01 * quadrature[c]);
  }
}
