// The effect planner: scene features against closed forms, the terms it decides from physical
// ratios, its predictions from calibration rows, and its choice under time and error budgets, on
// a calibration written in the test (so every expected choice follows from numbers seen here).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <lucent/plan/explain.hpp>
#include <lucent/plan/planner.hpp>
#include <lucent/scene/shapes.hpp>
#include <lucent/technique/registry.hpp>

#include "technique/core_registry.hpp"

namespace {
namespace lp = lucent::plan;
namespace lt = lucent::technique;
using lucent::scene::DirectionalLight;
using lucent::scene::EnvironmentLight;
using lucent::scene::Light;

/// A sphere of `material`, `sizeMm` across, seen along +z with `pixels` pixels across, `points`
/// of them shaded.
struct TestScene {
  lt::SceneDescription scene;
  lt::ShadeRequest request;
  lucent::scene::PinholeCamera camera;

  TestScene(double sizeMm, const char* material, std::vector<Light> lights, int pixels = 64) {
    scene.mesh = lucent::scene::shapes::sphere(1.0, 4);
    scene.mesh.scaleToSize(sizeMm);
    scene.vertexNormals = scene.mesh.vertexNormals();
    scene.medium.material = *lucent::optics::findMaterial(material);
    scene.lights = std::move(lights);
    camera = lucent::scene::PinholeCamera::frame(scene.mesh.bounds(), glm::dvec3(0, 0, 1), pixels,
                                                 pixels);
    request.camera = &camera;
    request.points.resize(std::size_t(pixels * pixels / 2));
  }
  lp::SceneFeatures features() const { return lp::sceneFeatures(scene, request, &camera); }
};

const Light kFront = DirectionalLight{glm::dvec3(0, 0, 1), glm::dvec3(1)};
const Light kBack = DirectionalLight{glm::dvec3(0, 0, -1), glm::dvec3(1)};

/// A setting measured on a scene with features f, taking seconds and erring modelError.
lp::SettingMeasurement measured(const std::string& scene, const lp::SceneFeatures& f,
                                const std::string& technique, const std::string& knobs,
                                double seconds, double modelError) {
  return {scene, f, technique, "dipole", knobs, seconds, 0.1 * seconds, 0.9 * seconds, modelError};
}

/// Four techniques measured on one calibration scene; the dipole's floor there is 0.02 and single
/// scattering carries 1 %.
lp::Calibration calibrationAt(const lp::SceneFeatures& f, double brdfError = 0.5) {
  lp::Calibration c;
  c.source = "the test";
  c.settings = {measured("cal", f, "reference", "fraction=1", 1.0, 0.001),
                measured("cal", f, "tsis", "samples=400", 0.1, 0.1),
                measured("cal", f, "tsis", "defaults", 0.3, 0.03),
                measured("cal", f, "tsm", "defaults", 0.05, 0.02),
                measured("cal", f, "diffuse-brdf", "env-strata=4", 0.001, brdfError)};
  c.floors = {{"cal", "dipole", f, 0.02, 0.01}};
  return c;
}

lp::Plan planOf(const TestScene& s, const lp::Calibration& c, const lp::Budget& b) {
  static const lt::Registry registry = lt::compiledCoreRegistry();
  return lp::makePlan(registry, s.scene, s.request, s.features(), c, b);
}

const lp::TermDecision& term(const lp::Plan& p, const std::string& start) {
  for (const auto& t : p.terms.terms)
    if (t.term.rfind(start, 0) == 0) return t;
  FAIL("no term " << start);
  return p.terms.terms.front();
}
}  // namespace

TEST_CASE("Scene features: a sphere's mean chord 4V/A is 2/3 of its diameter, lights' sides") {
  const TestScene s(30, "marble", {kFront});
  const lp::SceneFeatures f = s.features();
  CHECK(f.thicknessMm == doctest::Approx(30 / std::sqrt(3.0) * 2 / 3).epsilon(0.01));
  CHECK(f.backLitShare == 0);
  CHECK(TestScene(30, "marble", {kBack}).features().backLitShare == 1);
  EnvironmentLight env;
  env.width = env.height = 1, env.radiance = {glm::vec3(1)};
  const lp::SceneFeatures e = TestScene(30, "marble", {kFront, env}).features();
  CHECK(e.environmentShare == doctest::Approx(M_PI / (1 + M_PI)));
  CHECK(e.light == doctest::Approx(1 + M_PI));
  CHECK(e.backLitShare == doctest::Approx(0.5 * M_PI / (1 + M_PI)));
  // Marble (Jensen et al. 2001): sigma_s' = 2.19 / 2.62 / 3.00, sigma_a = 0.0021 / 0.0041 / 0.0071.
  CHECK(f.meanFreePathMm == doctest::Approx(1 / (2.19 + 0.0021)));
  CHECK(f.albedo == doctest::Approx(3.00 / (3.00 + 0.0071)));  // the lowest: blue
  CHECK(f.diffusionLengthMm == doctest::Approx(1 / std::sqrt(3 * 0.0021 * (2.19 + 0.0021))));
  const auto values = lp::featureValues(f);
  CHECK(lp::featureValues(lp::featuresFromValues(values)) == values);
}

TEST_CASE(
    "Terms: sub-pixel reach -> diffuse BRDF, front-lit -> local only, back-lit thin -> "
    "global, no light -> nothing") {
  const TestScene front(30, "marble", {kFront});
  const lp::Plan f = planOf(front, calibrationAt(front.features()), {});
  CHECK(f.terms.reach == lt::Reach::Local);
  CHECK_FALSE(term(f, "multiple scattering, global").simulated);
  CHECK(term(f, "multiple scattering, local").simulated);
  CHECK_FALSE(term(f, "single scattering").simulated);  // 1 % < 5 %

  const TestScene back(5, "skin1", {kBack});
  const lp::Plan b = planOf(back, calibrationAt(back.features()), {});
  CHECK(b.terms.reach == lt::Reach::Global);
  CHECK(term(b, "multiple scattering, global").simulated);
  // the local-only technique is left out, with the reason
  bool tsmExcluded = false;
  for (const auto& e : b.excluded)
    tsmExcluded |= e.rfind("tsm: its multiple scattering is local", 0) == 0;
  CHECK(tsmExcluded);

  const TestScene huge(20000, "skin1", {kFront}, 32);  // 13.7 mm reach, 0.4 m pixels
  const lp::Plan h = planOf(huge, calibrationAt(huge.features(), 0.004), {});
  CHECK(h.features.reachInPixels() < 1);
  CHECK(h.terms.reach == lt::Reach::Point);
  CHECK(term(h, "multiple scattering as a diffuse BRDF").simulated);
  REQUIRE(h.choice);
  CHECK(h.choice->technique->name == "diffuse-brdf");  // the fastest within 5 % there

  TestScene dark(30, "marble", {DirectionalLight{glm::dvec3(0, 0, 1), glm::dvec3(0)}});
  const lp::Plan d = planOf(dark, calibrationAt(dark.features()), {});
  CHECK_FALSE(d.terms.lit);
  CHECK_FALSE(term(d, "every term").simulated);
}

TEST_CASE(
    "Choice: the fastest within a target error, the most accurate within a time, the "
    "closest when none meets") {
  const TestScene back(5, "skin1", {kBack});
  const lp::Calibration cal = calibrationAt(back.features());
  // Errors against the physical truth: hypot(model error, floor 0.02).
  lp::Budget error;
  error.error = 0.05;
  lp::Plan p = planOf(back, cal, error);
  REQUIRE(p.choice);
  CHECK(p.meetsBudget);
  CHECK(p.choice->technique->name == "tsis");
  CHECK(p.choice->knobs == "defaults");  // 0.036 in 0.3 s; tsm (0.028, 0.05 s) is local only
  CHECK(p.choice->error == doctest::Approx(std::hypot(0.03, 0.02)).epsilon(1e-6));

  lp::Budget time;
  time.seconds = 2;
  p = planOf(back, cal, time);
  REQUIRE(p.choice);
  CHECK(p.choice->technique->name == "reference");  // the most accurate within 2 s

  lp::Budget tight;
  tight.seconds = 0.01, tight.hard = true;
  p = planOf(back, cal, tight);
  REQUIRE(p.choice);
  CHECK_FALSE(p.meetsBudget);
  CHECK(p.choice->knobs == "samples=400");  // the fastest that serves the terms
  const auto lines = lp::explain(p, tight);
  bool closest = false;
  for (const auto& l : lines) closest |= l.rfind("choice (closest, budget not met)", 0) == 0;
  CHECK(closest);
}

TEST_CASE(
    "Choice within a time: a faster setting whose image cannot differ from the most accurate by a "
    "display step is taken, and a setting worse than a black image is not chosen while another "
    "exists") {
  const TestScene back(5, "skin1", {kBack});
  const lp::SceneFeatures f = back.features();
  lp::Calibration cal;
  cal.source = "the test";
  cal.floors = {{"cal", "dipole", f, 0.02, 0.01}};
  // Two dipole settings 0.001 and 0.002 from the model's truth differ from each other by at most
  // 0.003, below a display step (1 %).
  cal.settings = {measured("cal", f, "reference", "fraction=1", 1.0, 0.001),
                  measured("cal", f, "tsis", "defaults", 0.3, 0.002)};
  lp::Budget time;
  time.seconds = 2;
  lp::Plan p = planOf(back, cal, time);
  REQUIRE(p.choice);
  CHECK(p.meetsBudget);
  CHECK(p.choice->technique->name == "tsis");
  REQUIRE(p.mostAccurate);
  CHECK(p.mostAccurate->technique->name == "reference");
  bool said = false;
  for (const auto& line : lp::explain(p, time))
    said |=
        line.find("instead of the most accurate within the time, reference") != std::string::npos;
  CHECK(said);
  // 0.001 and 0.02 from it: they may differ by 2.1 %, so the more accurate reference is chosen.
  cal.settings[1] = measured("cal", f, "tsis", "defaults", 0.3, 0.02);
  p = planOf(back, cal, time);
  REQUIRE(p.choice);
  CHECK(p.choice->technique->name == "reference");
  CHECK_FALSE(p.mostAccurate);

  // Only a setting three times worse than black fits 0.05 s: the plan is the closest usable one.
  cal.settings = {measured("cal", f, "reference", "fraction=1", 1.0, 0.001),
                  measured("cal", f, "tsis", "samples=400", 0.01, 3.0)};
  time.seconds = 0.05;
  p = planOf(back, cal, time);
  REQUIRE(p.choice);
  CHECK(p.choice->technique->name == "reference");
  CHECK_FALSE(p.meetsBudget);
}

TEST_CASE(
    "Predictions: a power law recovered from its own samples, a scene far from the "
    "calibration is flagged") {
  std::vector<lp::SettingMeasurement> rows;
  for (double points : {100.0, 1000.0, 10000.0})
    for (double area : {1e2, 1e4, 1e6}) {
      lp::SettingMeasurement m;
      m.features.shadedPoints = points, m.features.areaMm2 = area, m.features.meanFreePathMm = 1;
      m.seconds = 3e-6 * points * std::sqrt(area);
      rows.push_back(m);
    }
  std::vector<const lp::SettingMeasurement*> ptrs;
  for (const auto& r : rows) ptrs.push_back(&r);
  const lp::PowerLaw law = lp::fitPowerLaw(ptrs, [](const auto& m) { return m.seconds; });
  CHECK(law.slope[0] == doctest::Approx(1).epsilon(0.02));
  CHECK(law.slope[1] == doctest::Approx(0.5).epsilon(0.02));
  lp::SceneFeatures probe = rows[4].features;
  probe.shadedPoints = 3000;
  CHECK(law(probe) == doctest::Approx(3e-6 * 3000 * 100).epsilon(0.05));

  const TestScene near(30, "marble", {kFront});
  const TestScene far(30000, "marble", {kFront});
  CHECK(planOf(near, calibrationAt(near.features()), {}).outsideCalibration.empty());
  const auto outside = planOf(far, calibrationAt(near.features()), {}).outsideCalibration;
  REQUIRE_FALSE(outside.empty());
  CHECK(outside.front().rfind("size in mean free paths", 0) == 0);
}

TEST_CASE(
    "Calibration files: a bad field names the file, the line and the command that "
    "regenerates it") {
  const std::string dir = "planner-calibration-test";
  std::filesystem::create_directories(dir);
  std::string header = "scene";
  std::string row = "a";
  for (const char* name : lp::kFeatureNames) header += std::string(",") + name, row += ",1";
  {
    std::ofstream(dir + "/settings.csv")
        << header << ",technique,model,knobs,seconds,prepare_seconds,frame_seconds,"
        << "relative_rms_model\n"
        << row << ",tsis,dipole,\"samples=400\",0.5,0.1,0.4,0.03\n"
        << row << ",tsis,dipole,defaults,fast,0.1,0.4,0.03\n";
    std::ofstream(dir + "/model-floors.csv")
        << header << ",model,relative_rms_physical,single_share\n"
        << row << ",dipole,0.1,0.02\n";
  }
  try {
    lp::readCalibration(dir);
    FAIL("a bad number was read");
  } catch (const lp::CalibrationError& e) {
    const std::string what = e.what();
    CHECK(what.find(dir + "/settings.csv' line 3") != std::string::npos);
    CHECK(what.find("'fast', not a number") != std::string::npos);
    CHECK(what.find("calibrate_planner.py") != std::string::npos);
  }
  {
    std::ofstream(dir + "/settings.csv")
        << header << ",technique,model,knobs,seconds,prepare_seconds,frame_seconds,"
        << "relative_rms_model\n"
        << row << ",tsis,dipole,\"samples=400\",0.5,0.1,0.4,0.03\n";
  }
  const lp::Calibration c = lp::readCalibration(dir);
  REQUIRE(c.settings.size() == 1);
  CHECK(c.settings[0].knobs == "samples=400");
  CHECK(lp::knobPairs(c.settings[0].knobs) ==
        std::vector<std::pair<std::string, std::string>>{{"samples", "400"}});
  CHECK(c.floors.at(0).singleShare == 0.02);
  CHECK_THROWS_AS(lp::readCalibration(dir + "/missing"), lp::CalibrationError);
  std::filesystem::remove_all(dir);
}

TEST_CASE(
    "Where nothing that takes the scene carries multiple scattering, the best that takes it is "
    "chosen and the plan says what it leaves out") {
  TestScene s(30, "skin1", {kFront});
  s.scene.medium.density = [](const glm::dvec3&) { return 1.0; };  // heterogeneous, as a scan
  s.scene.medium.densityDescription = "a scan";
  lp::Calibration c = calibrationAt(s.features());
  c.settings.push_back(measured("cal", s.features(), "taulut", "defaults", 0.2, 0.05));
  const lp::Plan plan = planOf(s, c, lp::Budget{});
  REQUIRE(plan.choice);
  CHECK(plan.choice->technique->name == "taulut");
  CHECK(plan.termLeftOut.find("multiple scattering") != std::string::npos);
  bool said = false;
  for (const auto& line : lp::explain(plan, lp::Budget{}))
    said = said || line.find("note: no technique that takes this scene") != std::string::npos;
  CHECK(said);
  // With no calibrated technique that takes it at all, there is still no choice.
  const lp::Plan none = planOf(s, calibrationAt(s.features()), lp::Budget{});
  CHECK(!none.choice);
  CHECK(none.termLeftOut.empty());
}
