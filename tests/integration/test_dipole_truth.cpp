#include <doctest/doctest.h>

#include <cmath>

#include <lucent/image/metrics.hpp>
#include <lucent/optics/materials.hpp>
#include <lucent/reference/dipole_truth.hpp>
#include <lucent/reference/jensen_buhler.hpp>
#include <lucent/scene/shapes.hpp>

#include "raycast/embree_ray_caster.hpp"
#include "small_scene.hpp"
#include "util/tbb_parallel.hpp"

using namespace lucent;
using test::dipoleOf;
using test::SmallScene;

TEST_CASE(
    "Flat slab under normal light: B at the centre equals E_t x the total diffuse reflectance") {
  // A 120 x 120 x 20 mm skin1 slab lit head-on. Far from the edges the surface is a semi-infinite
  // medium, where int_A Rd dA = Rd_total (Jensen 2001, Eq. 14): an analytic truth for the
  // brute-force sum. The square is wide enough (60 mm >> 1/sigma_tr = 3.7 mm) that the missing tail
  // is below 1e-6.
  scene::TriangleMesh slab = scene::shapes::box(glm::dvec3(60, 60, 10), 4.0);
  raycast::EmbreeRayCaster caster(slab);
  const auto d = dipoleOf<double>("skin1");
  std::vector<scene::Light> light{scene::DirectionalLight{glm::dvec3(0, 0, 1), glm::dvec3(1)}};
  scene::IrradianceSettings irr;
  irr.eta = 1.3;
  irr.rayEpsilon = 1e-4;
  const double et = optics::fresnelTransmittance(1.0, 1.3);
  double previousError = 1e30;
  for (double fraction : {0.5, 0.25}) {
    const auto samples = reference::buildSurfaceSamples(slab, fraction * d.minMeanFreePath());
    const reference::DipoleTruth<double> truth(samples, d, light, caster, irr, util::tbbFor);
    // Away from the sample lattice's symmetry points: a generic point near the centre.
    const glm::dvec3 b = truth.radiosity(glm::dvec3(0.0123, -0.0371, 10.0));
    double worst = 0;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(b[c] / (et * d.total()[c]) - 1));
    INFO("spacing " << fraction << " mfp: worst relative error " << worst << " (" << samples.size()
                    << " samples)");
    CHECK(worst <
          1e-5);  // measured 6e-8 at mfp/2: the midpoint rule on a flat lattice is superconvergent
    CHECK(worst < previousError);
    previousError = worst;
  }
}

TEST_CASE("The brute-force truth converges as the sample spacing shrinks") {
  // A coarse icosphere (edges ~0.8 mm), so every spacing below subdivides its triangles
  // differently.
  const SmallScene s(scene::shapes::sphere(1.0, 2), 10.0, 48);
  const auto d = dipoleOf<float>("skin1");
  const double mfp = d.minMeanFreePath();
  const image::Image finest = s.render(d, mfp / 8);
  std::vector<double> errors;
  for (double f : {1.0, 0.5, 0.25})
    errors.push_back(image::compareImages(s.render(d, f * mfp), finest).relativeRms);
  INFO("relative RMS at mfp, mfp/2, mfp/4 against mfp/8: " << errors[0] << " " << errors[1] << " "
                                                           << errors[2]);
  CHECK(errors[0] > errors[1]);
  CHECK(errors[1] > errors[2]);
  CHECK(errors[2] <
        errors[0] / 4);  // at least first order overall (second order where Rd is smooth)
  CHECK(errors[2] < 0.01);
}

TEST_CASE("The float truth (vectorised kernel) agrees with the double truth (std::exp)") {
  const SmallScene s(scene::shapes::torus(), 20.0, 40);
  const double spacing = 0.5 * dipoleOf<double>("marble").minMeanFreePath();
  const image::Image f = s.render(dipoleOf<float>("marble"), spacing);
  const image::Image d = s.render(dipoleOf<double>("marble"), spacing);
  const image::ImageErrors e = image::compareImages(f, d);
  INFO("relative RMS float vs double: " << e.relativeRms);
  CHECK(e.coveredPixels > 100);
  CHECK(e.relativeRms < 1e-5);
}

TEST_CASE(
    "Hard cases render finite, non-negative images: spectralon, eta = 1 and 2.5, 0.01 mm, 10 m, "
    "thin twirl") {
  struct Case {
    const char* what;
    scene::TriangleMesh mesh;
    double size;
    const char* material;
    double eta;
  };
  const Case cases[] = {{"spectralon sphere", scene::shapes::sphere(1, 3), 10, "spectralon", -1},
                        {"eta 1", scene::shapes::sphere(1, 3), 10, "skin1", 1.0},
                        {"eta 2.5", scene::shapes::sphere(1, 3), 10, "skin1", 2.5},
                        {"0.01 mm", scene::shapes::sphere(1, 3), 0.01, "skin1", -1},
                        {"10 m", scene::shapes::sphere(1, 3), 1e4, "cream", -1},
                        {"thin twirl", scene::shapes::twirl(), 30, "ketchup", -1},
                        {"near-clear liquid", scene::shapes::torus(), 30, "sprite", -1}};
  for (const auto& c : cases) {
    INFO(c.what);
    const SmallScene s(c.mesh, c.size, 24);
    const auto d = dipoleOf<float>(c.material, c.eta);
    const auto choice = reference::chooseSpacing(s.mesh, d.minMeanFreePath(), 0.5, 200000);
    const image::Image img = s.render(d, choice.spacing);
    int covered = 0, lit = 0;
    for (const auto& p : img.pixels) {
      for (int k = 0; k < 3; ++k) {
        REQUIRE(std::isfinite(p[k]));
        REQUIRE(p[k] >= 0);
      }
      covered += p.a > 0.5f;
      lit += p.r > 0;
    }
    CHECK(covered > 50);
    CHECK(lit > 0);
  }
}

TEST_CASE("Spacing choice: a fraction of the mean free path, coarsened only by the sample budget") {
  scene::TriangleMesh m = scene::shapes::sphere(1, 2);  // 320 triangles
  m.scaleToSize(10);
  const auto fine = reference::chooseSpacing(m, 0.2, 0.5, 10000000);
  CHECK(fine.spacing == doctest::Approx(0.1));
  CHECK_FALSE(fine.budgetLimited);
  // Never coarser than diag/64, whatever the mean free path (the geometry must be resolved).
  CHECK(reference::chooseSpacing(m, 100.0, 0.5, 10000000).spacing == doctest::Approx(10.0 / 64));
  const auto limited = reference::chooseSpacing(m, 0.2, 0.5, 1000);
  CHECK(limited.budgetLimited);
  CHECK(reference::countSurfaceSamples(m, limited.spacing) <= 1000);
  // A budget below the triangle count: it terminates at one sample per triangle.
  const auto floor = reference::chooseSpacing(m, 0.2, 0.5, 10);
  CHECK(floor.budgetLimited);
  CHECK(reference::countSurfaceSamples(m, floor.spacing) == m.triangles.size());
}

TEST_CASE(
    "Environment light: a uniform sky gives E = 2 pi L int_0^1 Ft(mu) mu dmu on a convex object") {
  scene::TriangleMesh m = scene::shapes::sphere(1, 5);
  m.scaleToSize(10);
  raycast::EmbreeRayCaster caster(m);
  scene::EnvironmentLight sky;
  sky.width = sky.height = 1;
  sky.radiance = {glm::vec3(2.0f, 1.0f, 0.5f)};
  const std::vector<scene::Light> lights{sky};
  scene::IrradianceSettings irr;
  irr.eta = 1.3;
  irr.rayEpsilon = 1e-4;
  irr.environmentStrata = 16;
  double expectedPerUnit =
      0;  // 2 pi int_0^1 Ft(mu) mu dmu by the midpoint rule, independent of the sampler
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double mu = (i + 0.5) / n;
    expectedPerUnit += 2 * optics::kPi * optics::fresnelTransmittance(mu, 1.3) * mu / n;
  }
  const auto samples = reference::buildSurfaceSamples(m, 1.0);
  glm::dvec3 mean(0);
  for (std::size_t i = 0; i < samples.size(); ++i)
    mean += scene::irradianceAt(samples.position[i], samples.normal[i], samples.faceNormal[i],
                                lights, caster, irr, i);
  mean /= double(samples.size());
  INFO("mean E " << mean.x << " " << mean.y << " " << mean.z << ", expected "
                 << 2 * expectedPerUnit);
  CHECK(mean.x == doctest::Approx(2.0 * expectedPerUnit).epsilon(0.01));
  CHECK(mean.z == doctest::Approx(0.5 * expectedPerUnit).epsilon(0.01));
}

TEST_CASE("Jensen-Buhler: epsilon = 0 is the exact sum, the error shrinks with epsilon") {
  const SmallScene s(scene::shapes::torus(), 20.0, 40);
  const auto d = dipoleOf<double>("skin1");
  const auto samples = reference::buildSurfaceSamples(s.mesh, 0.5 * d.minMeanFreePath());
  const reference::DipoleTruth<double> truth(samples, d, s.lights, *s.caster, s.irr, util::tbbFor);
  const auto hits = reference::primaryHits(s.camera, s.mesh, s.normals, *s.caster, util::tbbFor);
  const image::Image exact = reference::renderTruth(truth, s.camera, hits, util::tbbFor);

  const reference::JensenBuhlerTree<double> zero(truth, 0.0);
  for (const glm::dvec3 p : {glm::dvec3(1, 2, 3), glm::dvec3(0), glm::dvec3(-5, 0.5, 1)}) {
    const glm::dvec3 a = zero.radiosity(p), b = truth.radiosity(p);
    for (int c = 0; c < 3; ++c) CHECK(a[c] == doctest::Approx(b[c]).epsilon(1e-12));
  }
  std::vector<double> errors;
  for (double eps : {0.5, 0.1, 0.02}) {
    const reference::JensenBuhlerTree<double> tree(truth, eps);
    errors.push_back(
        image::compareImages(reference::renderTruth(tree, s.camera, hits, util::tbbFor), exact)
            .relativeRms);
  }
  INFO("relative RMS at epsilon 0.5, 0.1, 0.02: " << errors[0] << " " << errors[1] << " "
                                                  << errors[2]);
  CHECK(errors[0] > errors[1]);
  CHECK(errors[1] > errors[2]);
  CHECK(errors[2] < 0.01);

  // In float the octree gathers its sources into the vectorised kernel; the double tree sums them
  // one Rd at a time. The traversal is the same, so the sums agree to float rounding: this checks
  // the gather (whole nodes and leaf ranges) at every epsilon.
  const auto df = dipoleOf<float>("skin1");
  const reference::DipoleTruth<float> truthF(samples, df, s.lights, *s.caster, s.irr, util::tbbFor);
  for (double eps : {0.0, 0.1, 0.5}) {
    const reference::JensenBuhlerTree<double> treeD(truth, eps);
    const reference::JensenBuhlerTree<float> treeF(truthF, eps);
    for (const glm::dvec3 p : {glm::dvec3(1, 2, 3), glm::dvec3(0), glm::dvec3(-5, 0.5, 1),
                               glm::dvec3(s.mesh.positions[7])}) {
      const glm::dvec3 a = treeF.treeSum(p), b = treeD.treeSum(p);
      INFO("epsilon " << eps << " float " << a.x << " double " << b.x);
      for (int c = 0; c < 3; ++c) {
        CHECK(b[c] > 0);  // relative agreement means something only for a lit sum
        CHECK(std::abs(a[c] - b[c]) <= 2e-4 * std::abs(b[c]));
      }
    }
    CHECK(treeF.termCount() == treeD.termCount());
  }
}
