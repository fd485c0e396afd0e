#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <string>

#include <lucent/reference/volume_path_tracer.hpp>
#include <lucent/scene/shapes.hpp>

#include "../unit/chandrasekhar_h.hpp"
#include "path_trace_estimate.hpp"
#include "raycast/embree_ray_caster.hpp"
#include "util/tbb_parallel.hpp"

using namespace lucent;

namespace {
using namespace lucent::test;

void checkWithin(const Estimate& e, const glm::dvec3& exact, double sigmas,
                 const std::string& what) {
  for (int c = 0; c < 3; ++c) {
    INFO(what << " channel " << c << ": " << e.mean[c] << " +- " << e.stdError[c] << ", exact "
              << exact[c]);
    CHECK(std::abs(e.mean[c] - exact[c]) <= sigmas * e.stdError[c] + 1e-12);
  }
}
}  // namespace

TEST_CASE("White furnace: albedo-1 media under uniform light return exactly the light's radiance") {
  // Radiance invariance: with no absorption and L = 1 from every direction, L = 1 everywhere,
  // whatever the shape, the indices, the nesting or the density field. Surface reflection included.
  const double R = 1.0;
  const auto env = uniformEnvironment(1.0);
  reference::PathTracerSettings s;
  s.rayEpsilon = 1e-6;

  SUBCASE("a Fresnel sphere (eta 1.3), sigma_s differing 4x between channels") {
    reference::MediumScene scene;
    scene.addBody(scene::shapes::sphere(R, 4),
                  scene.addMedium(medium(glm::dvec3(0), {1, 2, 4}, 1.3, 0.5)), 0);
    const raycast::EmbreeRayCaster caster(scene.mesh);
    const reference::VolumePathTracer tracer(scene, caster, {env}, s);
    const Estimate e = estimate(
        tracer, 40000, [&](std::size_t, util::Rng& rng) { return rayThroughSphere(R, rng); }, 1);
    checkWithin(e, glm::dvec3(1), 4, "Fresnel sphere");
    checkClean(e.stats);
  }
  SUBCASE("a cube with a spherical cavity holding an inclusion of another index, a density field") {
    reference::MediumScene scene;
    reference::Medium outer = medium(glm::dvec3(0), {3, 2, 1}, 1.3);
    outer.density = [](const glm::dvec3& p) {
      return 0.55 + 0.45 * std::sin(5 * p.x) * std::cos(4 * p.y);
    };
    const auto outerId = scene.addMedium(outer);
    const auto innerId = scene.addMedium(medium(glm::dvec3(0), {6, 6, 6}, 1.6, -0.3));
    scene.addBody(scene::shapes::cubeWithCavity(0.6), outerId,
                  0);  // cube of side 2, cavity radius 0.6
    scene.addBody(scene::shapes::sphere(0.35, 3), innerId,
                  0);  // inclusion inside the (vacuum) cavity
    const raycast::EmbreeRayCaster caster(scene.mesh);
    const reference::VolumePathTracer tracer(scene, caster, {env}, s);
    const Estimate e = estimate(
        tracer, 30000, [&](std::size_t, util::Rng& rng) { return rayThroughSphere(1.0, rng); }, 2);
    checkWithin(e, glm::dvec3(1), 4, "cube with cavity");
    checkClean(e.stats);
    CHECK(e.stats.scatterEvents > 30000);
  }
}

TEST_CASE(
    "Russian roulette reads the physical throughput: behind eta 1.3, a non-absorbing grey medium "
    "ends no path, and returns the furnace's radiance") {
  // Entering eta 1.3 scales a camera path's radiance by (1/1.3)^2, which its exit undoes. Read as
  // a loss of throughput it ended 41 % of these paths at their 4th scatter.
  const double R = 1.0;
  const auto env = uniformEnvironment(1.0);
  reference::PathTracerSettings s;
  s.rayEpsilon = 1e-6;
  reference::MediumScene scene;
  scene.addBody(scene::shapes::sphere(R, 4),
                scene.addMedium(medium(glm::dvec3(0), glm::dvec3(4), 1.3)), 0);
  const raycast::EmbreeRayCaster caster(scene.mesh);
  const reference::VolumePathTracer tracer(scene, caster, {env}, s);
  const Estimate e = estimate(
      tracer, 20000, [&](std::size_t, util::Rng& rng) { return rayThroughSphere(R, rng); }, 3);
  checkWithin(e, glm::dvec3(1), 4, "grey Fresnel sphere");
  checkClean(e.stats);
  CHECK(e.stats.scatterEvents > 4 * e.stats.cameraSamples);  // deep enough for roulette to act
  CHECK(e.stats.rouletteTerminations == 0);
}

TEST_CASE(
    "Index-matched isotropic half-space: reflected radiance = (a E / 4pi) H(mu) H(1) / (1 + mu)") {
  // Chandrasekhar (1960): diffuse reflection of a normally incident parallel beam by a
  // semi-infinite, isotropically scattering medium; its single-scattering part is (a E / 4pi) / (1
  // + mu). A box of 400 x 400 x 200 mean free paths stands in for the half-space (leakage ~
  // exp(-100)).
  const double albedo = 0.8;
  reference::MediumScene scene;
  scene.addBody(scene::shapes::box(glm::dvec3(200, 200, 100), 100.0),
                scene.addMedium(medium(glm::dvec3(1 - albedo), glm::dvec3(albedo), 1.0)), 0);
  for (auto& p : scene.mesh.positions) p.z -= 100;  // top face at z = 0
  const raycast::EmbreeRayCaster caster(scene.mesh);
  const std::vector<scene::Light> lights{
      scene::DirectionalLight{glm::dvec3(0, 0, 1), glm::dvec3(1.0)}};
  for (double mu : {1.0, 0.5}) {
    const glm::dvec3 toEye(std::sqrt(1 - mu * mu), 0, mu);
    auto rayOf = [&](std::size_t, util::Rng& rng) {
      const glm::dvec3 target(4 * rng.uniform() - 2, 4 * rng.uniform() - 2, 0);
      return scene::Ray{target + 50.0 * toEye, -toEye};
    };
    const double h = test::chandrasekharH(mu, albedo), h1 = test::chandrasekharH(1.0, albedo);
    const double scale = albedo / (4 * optics::kPi) / (1 + mu);
    for (auto [orders, exact, label] :
         {std::tuple{reference::ScatteringOrders::All, scale * h * h1, "all orders"},
          std::tuple{reference::ScatteringOrders::Single, scale, "single"},
          std::tuple{reference::ScatteringOrders::Multiple, scale * (h * h1 - 1), "multiple"}}) {
      reference::PathTracerSettings s;
      s.orders = orders;
      const reference::VolumePathTracer tracer(scene, caster, lights, s);
      CHECK_FALSE(tracer.joinsDeltaLights());
      const Estimate e = estimate(tracer, 20000, rayOf, 3);
      checkWithin(e, glm::dvec3(exact), 4, std::string(label) + " at mu " + std::to_string(mu));
      checkClean(e.stats);
    }
  }
}

TEST_CASE(
    "A chromatic half-space, each channel its own Chandrasekhar solution, with the hero channel "
    "chosen by reflectance and by uniform choice") {
  // Per channel the half-space's reflection depends on its albedo alone, not on sigma_t, so the
  // channels' extinctions (1, 2, 4) differ while each has an exact answer: the one-sample MIS over
  // channels must weight distances drawn with another channel's sigma_t right, for a hero chosen
  // with P far from uniform as for P = 1/3.
  const glm::dvec3 albedo(0.95, 0.6, 0.3), sigmaT(1, 2, 4);
  reference::MediumScene scene;
  scene.addBody(scene::shapes::box(glm::dvec3(200, 200, 100), 100.0),
                scene.addMedium(medium(sigmaT * (glm::dvec3(1) - albedo), sigmaT * albedo, 1.0)),
                0);
  for (auto& p : scene.mesh.positions) p.z -= 100;  // top face at z = 0
  const raycast::EmbreeRayCaster caster(scene.mesh);
  const std::vector<scene::Light> lights{
      scene::DirectionalLight{glm::dvec3(0, 0, 1), glm::dvec3(1.0)}};
  const test::HalfSpaceView view = test::halfSpaceView(0.6, albedo);
  const glm::dvec3& exact = view.exact;
  auto rayOf = [&](std::size_t, util::Rng& rng) { return view.rayAt(rng); };
  for (auto choice : {reference::HeroChoice::Reflectance, reference::HeroChoice::Uniform}) {
    reference::PathTracerSettings s;
    s.heroChoice = choice;
    const reference::VolumePathTracer tracer(scene, caster, lights, s);
    if (choice == reference::HeroChoice::Reflectance) {
      CHECK(tracer.heroChoice().x > 0.5);  // red reflects most: chosen most
      CHECK(tracer.heroChoice().z > 0.2 / 3);
    } else {
      CHECK(tracer.heroChoice() == glm::dvec3(1.0 / 3));
    }
    const Estimate e = estimate(tracer, 40000, rayOf, 7);
    checkWithin(e, exact, 4,
                choice == reference::HeroChoice::Reflectance ? "reflectance" : "uniform");
    for (int c = 0; c < 3; ++c) CHECK(e.stdError[c] < 0.03 * exact[c]);
    checkClean(e.stats);
  }
}

TEST_CASE("Behind a Fresnel boundary, light subpaths joined to the camera equal escaping paths") {
  // Two independent estimators of the same paths (those with a straight scatter-to-scatter
  // segment): the camera walk escaping to a bright environment cap, and light subpaths sampled from
  // that cap, refracted in, and joined to camera segments by equiangular sampling. The (n1/n2)^2
  // radiance factor, the guided disc pdf and the hero-channel weights must all be right for them to
  // agree.
  scene::EnvironmentLight cap;
  cap.width = 8, cap.height = 8;
  cap.radiance.assign(64, glm::vec3(0.02f));
  for (int col = 0; col < 8; ++col)
    cap.radiance[std::size_t(col)] = glm::vec3(4.0f);  // the top row: a 22.5 deg cap
  reference::MediumScene scene;
  scene.addBody(scene::shapes::sphere(1.0, 4),
                scene.addMedium(medium({0.3, 0.1, 0.02}, {2, 3, 5}, 1.3, 0.3)), 0);
  const raycast::EmbreeRayCaster caster(scene.mesh);
  reference::PathTracerSettings escape;
  escape.connectableOnly = true;
  reference::PathTracerSettings join = escape;
  join.environment = reference::EnvironmentStrategy::Connect;
  join.lightSubpaths = 2;
  auto rayOf = [&](std::size_t, util::Rng& rng) { return rayThroughSphere(1.0, rng); };
  const Estimate a =
      estimate(reference::VolumePathTracer(scene, caster, {cap}, escape), 600000, rayOf, 4);
  const Estimate b =
      estimate(reference::VolumePathTracer(scene, caster, {cap}, join), 300000, rayOf, 5);
  checkAgree(a, b, 0.035, "escape against joined");  // a test that could tell a 14 % error
  checkClean(a.stats);
  checkClean(b.stats);
  CHECK(b.stats.connections > 0);
}

TEST_CASE("Delta tracking: a constant density field matches the homogeneous medium") {
  reference::MediumScene homogeneous, field;
  homogeneous.addBody(scene::shapes::sphere(1.0, 4),
                      homogeneous.addMedium(medium({0.4, 0.2, 0.1}, {1, 2, 3}, 1.3)), 0);
  reference::Medium m = medium({0.8, 0.4, 0.2}, {2, 4, 6}, 1.3);
  m.density = [](const glm::dvec3&) {
    return 0.5;
  };  // half of a majorant of 1: many null collisions
  field.addBody(scene::shapes::sphere(1.0, 4), field.addMedium(m), 0);
  scene::EnvironmentLight sky;
  sky.width = 2, sky.height = 2;
  sky.radiance = {glm::vec3(3.0f), glm::vec3(1.0f), glm::vec3(0.1f), glm::vec3(0.0f)};
  const raycast::EmbreeRayCaster casterA(homogeneous.mesh), casterB(field.mesh);
  reference::PathTracerSettings s;
  auto rayOf = [&](std::size_t, util::Rng& rng) { return rayThroughSphere(1.0, rng); };
  const Estimate a =
      estimate(reference::VolumePathTracer(homogeneous, casterA, {sky}, s), 40000, rayOf, 6);
  const Estimate b =
      estimate(reference::VolumePathTracer(field, casterB, {sky}, s), 40000, rayOf, 7);
  for (int c = 0; c < 3; ++c) {
    INFO("channel " << c << ": homogeneous " << a.mean[c] << ", field " << b.mean[c]);
    CHECK(std::abs(a.mean[c] - b.mean[c]) <= 4 * std::hypot(a.stdError[c], b.stdError[c]));
  }
  checkClean(b.stats);
}

TEST_CASE(
    "Path-traced images repeat for a fixed seed whatever the thread count, hard cases stay "
    "finite") {
  const auto env = uniformEnvironment(1.0);
  const std::vector<scene::Light> lights{
      env, scene::DirectionalLight{glm::dvec3(0, 0.5, -1), glm::dvec3(1)},
      scene::PointLight{glm::dvec3(0, 3, 3), glm::dvec3(18)}};
  struct Case {
    const char* name;
    double size, eta;
    glm::dvec3 sigmaA, sigmaS;
  };
  for (const Case& c : {Case{"zero absorption", 1, 1.3, glm::dvec3(0), {1, 2, 4}},
                        Case{"tiny (1 um)", 1e-3, 1.3, {0.01, 0.02, 0.03}, {1, 2, 3}},
                        Case{"huge (1 m), dense", 1000, 1.3, {0.5, 1, 2}, {20, 30, 40}},
                        Case{"extreme index 3.0", 1, 3.0, {0.1, 0.1, 0.1}, {1, 1, 1}},
                        Case{"index-matched", 1, 1.0, {0.1, 0.1, 0.1}, {1, 1, 1}}}) {
    INFO(std::string(c.name));
    scene::TriangleMesh mesh = scene::shapes::torus(1.0, 0.4, 32, 16);
    mesh.scaleToSize(c.size);
    reference::MediumScene scene;
    scene.addBody(mesh, scene.addMedium(medium(c.sigmaA, c.sigmaS, c.eta)), 0);
    const raycast::EmbreeRayCaster caster(scene.mesh);
    reference::PathTracerSettings s;
    s.samplesPerPixel = 4;
    s.rayEpsilon = 1e-5 * c.size;
    s.maxEvents = 20000;
    const reference::VolumePathTracer tracer(scene, caster, lights, s);
    const auto camera =
        scene::PinholeCamera::frame(scene.mesh.bounds(), glm::dvec3(0.2, 0.4, 1), 12, 12);
    const auto serial = reference::renderPathTraced(tracer, caster, camera, s);
    const auto parallel = reference::renderPathTraced(tracer, caster, camera, s, util::tbbFor);
    std::size_t covered = 0;
    for (std::size_t i = 0; i < serial.image.pixels.size(); ++i) {
      const glm::vec4 p = serial.image.pixels[i];
      CHECK(p == parallel.image.pixels[i]);
      CHECK(std::isfinite(p.x + p.y + p.z));
      CHECK(p.x >= 0);
      covered += serial.image.covered(i);
    }
    CHECK(covered > 20);
    CHECK(serial.stats.nonFiniteSamples == 0);
    CHECK(serial.stats.mediumMismatches == 0);
  }
}
