// vtkLucentPass's diffuse-brdf twin against diffuse-brdf on the CPU, and Technique auto: the
// planner's choice per frame, which follows the pixel the object covers.
#include <doctest/doctest.h>

#include <string>

#include <vtkCamera.h>

#include <lucent/scene/shapes.hpp>

#include "cpu_agreement.hpp"
#include "pass_scene.hpp"

namespace {
using lucent::vtkadapter::polyDataOf;
using lucent_test::Frame;
using lucent_test::lastFrame;
using lucent_test::PassScene;

bool startsWith(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

/// A skin sphere 300 mm across (22 reaches of Rd: inside diffuse-brdf's range), lit from
/// `toward`, drawn once by `technique` in a square view of `pixels`.
struct SkinSphere {
  lucent::scene::TriangleMesh world = lucent::scene::shapes::sphere(1.0, 5);
  PassScene scene;
  SkinSphere(const char* technique, const double toward[3], int pixels)
      : scene(polyDataOf(world), toward, pixels) {
    scene.pass->SetTechnique(technique);
    scene.pass->SetMaterial("skin1");
    scene.pass->SetSizeMm(300);
    scene.render();
  }
};
}  // namespace

TEST_CASE(
    "vtkLucentPass diffuse-brdf: per-pixel radiance matches diffuse-brdf on the CPU (Rd_total "
    "times the shadowed, Fresnel-transmitted irradiance), for the classic and the better dipole") {
  const double toward[3] = {0.6, 0.5, 0.6};
  SkinSphere sphere("diffuse-brdf", toward, 96);
  PassScene& scene = sphere.scene;
  // The better dipole's exit scale is not 1: the uniform that carries it is checked too.
  for (const char* profile : {"dipole", "better-dipole"}) {
    scene.pass->SetKnob("diffuse-brdf.profile", profile);
    scene.render();
    INFO(profile << ": " << std::string(scene.pass->GetLastError()));
    REQUIRE(scene.pass->GetTranslucentActorCount() == 1);
    const Frame f = lastFrame(scene.pass);
    REQUIRE(f.covered() > 1500);
    CHECK(f.allFiniteNonNegative());
    const auto a = lucent_test::compareWithCpu(f, sphere.world, 300, "skin1",
                                               glm::dvec3(toward[0], toward[1], toward[2]),
                                               "diffuse-brdf", {{"profile", profile}});
    // One formula on both sides, in float on the GPU: agreement to float rounding, not to a
    // sampling error.
    lucent_test::checkAgreement(a, std::string("diffuse-brdf, ") + profile, 1e-4, 1e-3);
  }
}

TEST_CASE(
    "vtkLucentPass auto: up close the plan is tsis's twin, far away, where Rd's reach is below a "
    "pixel, diffuse-brdf's, which draws no samples, both frames finite") {
  const double toward[3] = {0.3, 0.4, 1.0};
  SkinSphere sphere("auto", toward, 128);
  PassScene& scene = sphere.scene;
  INFO(std::string(scene.pass->GetLastError()));
  REQUIRE(scene.pass->GetTranslucentActorCount() == 1);
  const std::string close = scene.pass->GetChosenTechnique();
  const std::string closePlan = scene.pass->GetLastPlan();
  INFO("close: " << close << "\n" << closePlan);
  CHECK(startsWith(close, "tsis"));
  CHECK(closePlan.find("scene:") != std::string::npos);
  const Frame near = lastFrame(scene.pass);
  CHECK(near.covered() > 2000);
  CHECK(near.allFiniteNonNegative());

  scene.renderer->GetActiveCamera()->Dolly(1.0 / 40);  // 40 times as far: a few pixels across
  scene.renderer->ResetCameraClippingRange();
  scene.render();
  const std::string far = scene.pass->GetChosenTechnique();
  INFO("far: " << far << "\n" << scene.pass->GetLastPlan());
  CHECK(startsWith(far, "diffuse-brdf"));
  const Frame distant = lastFrame(scene.pass);
  CHECK(distant.covered() > 0);
  CHECK(distant.covered() < 200);
  CHECK(distant.allFiniteNonNegative());
}

TEST_CASE("vtkLucentPass auto: a missing calibration is reported with the file and the fix") {
  const auto world = lucent::scene::shapes::sphere(1.0, 3);
  const double toward[3] = {0, 0, 1};
  PassScene scene(polyDataOf(world), toward, 32);
  scene.pass->SetTechnique("auto");
  scene.pass->SetCalibrationDirectory("/nonexistent/lucent-calibration");
  scene.pass->GlobalWarningDisplayOff();
  scene.render();
  const std::string error = scene.pass->GetLastError();
  INFO(error);
  CHECK(error.find("/nonexistent/lucent-calibration/settings.csv") != std::string::npos);
  CHECK(error.find("calibrate_planner.py") != std::string::npos);
  scene.pass->GlobalWarningDisplayOn();
}
