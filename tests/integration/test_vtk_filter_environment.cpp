// vtkLucentFilter under an environment map (EnvironmentFileName), and prt through it: the filter's
// scene equals the CLI's (the same technique run by the application's registry on the filter's own
// surface, with Embree), and a frame-phase knob (prt.rotate) re-runs only the frame.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>

#include <lucent/image/image.hpp>
#include <lucent/image/metrics.hpp>
#include <lucent/optics/materials.hpp>
#include <lucent/technique/registry.hpp>

#include "io/exr_io.hpp"
#include "lucentPolyDataMesh.h"
#include "raycast/embree_ray_caster.hpp"
#include "scene/synthetic_sky.hpp"
#include "technique/techniques.hpp"
#include "temp_dir.hpp"
#include "util/tbb_parallel.hpp"
#include "vtkLucentFilter.h"

namespace {
namespace lt = lucent::technique;

/// The synthetic sky (a gradient and a small, bright sun) as a lat-long EXR in `path`.
lucent::scene::EnvironmentLight writeSky(const std::string& path) {
  const auto sky = lucent::scene::syntheticSky();
  lucent::image::Image img(sky.width, sky.height);
  for (std::size_t i = 0; i < sky.radiance.size(); ++i)
    img.pixels[i] = glm::vec4(sky.radiance[i], 1.0f);
  lucent::io::writeExr(path, img);
  return sky;
}

std::vector<glm::dvec3> radianceOf(vtkPolyData* out) {
  vtkDataArray* a = out->GetPointData()->GetArray("Radiance");
  std::vector<glm::dvec3> v;
  if (!a) return v;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    v.emplace_back(a->GetComponent(i, 0), a->GetComponent(i, 1), a->GetComponent(i, 2));
  return v;
}

const lt::KnobList kPrtKnobs = {{"cube", "8"}, {"max-samples", "1500"}, {"single", "off"}};

/// prt run by the application's registry (Embree) on the filter's output surface, under `sky`.
std::vector<glm::dvec3> applicationPrt(vtkPolyData* surface,
                                       const lucent::scene::EnvironmentLight& sky,
                                       const std::string& rotate) {
  lt::SceneDescription scene;
  scene.mesh = lucent::vtkadapter::meshFromData(surface).mesh;
  scene.vertexNormals = scene.mesh.vertexNormals();
  const lucent::raycast::EmbreeRayCaster caster(scene.mesh);
  scene.caster = &caster;
  scene.parallelFor = lucent::util::tbbFor;
  scene.medium.material = *lucent::optics::findMaterial("skin1");
  scene.lights = {sky};
  const lt::Registry& registry = lt::appRegistry();
  const lt::Technique& prt = registry.get("prt");
  lt::KnobList knobs = kPrtKnobs;
  knobs.emplace_back("rotate", rotate);
  return registry.render(prt, scene, prt.values(knobs), lt::vertexRequest(scene.mesh))
      .frame.radiance;
}

void setPrtKnobs(vtkLucentFilter* filter) {
  filter->SetTechnique("prt");
  for (const auto& [name, value] : kPrtKnobs)
    filter->SetKnob(("prt." + name).c_str(), value.c_str());
}
}  // namespace

TEST_CASE(
    "vtkLucentFilter: prt under an environment map equals the application's prt on the same "
    "surface, turning the map (prt.rotate) re-runs only the frame, and a new surface, size or "
    "material prepares again") {
  const lucent::test::TempDir dir;
  const std::string skyPath = dir / "sky.exr";
  const auto sky = writeSky(skyPath);
  vtkNew<vtkSphereSource> sphere;  // 20 mm across, in mm
  sphere->SetRadius(10);
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(16);
  vtkNew<vtkLucentFilter> filter;
  filter->SetInputConnection(sphere->GetOutputPort());
  setPrtKnobs(filter);
  filter->SetEnvironmentFileName(skyPath.c_str());
  filter->Update();
  const auto first = radianceOf(filter->GetOutput());
  REQUIRE(first.size() > 100);
  CHECK_FALSE(filter->GetPrepareReused());
  CHECK(filter->GetPrepareSeconds() > 0);
  const auto expected = applicationPrt(filter->GetOutput(), sky, "0");
  REQUIRE(expected.size() == first.size());
  const double agree = lucent::image::relativeRms(first, expected);
  MESSAGE("filter's prt against the application's: relative RMS " << agree);
  CHECK(agree < 0.01);

  filter->SetKnobReal("prt.rotate", 90);
  filter->Update();
  const auto turned = radianceOf(filter->GetOutput());
  CHECK(filter->GetPrepareReused());
  CHECK(filter->GetPrepareSeconds() == 0);
  CHECK(lucent::image::relativeRms(turned, first) > 0.1);  // the sun moved
  const double turnedAgree =
      lucent::image::relativeRms(turned, applicationPrt(filter->GetOutput(), sky, "90"));
  MESSAGE("turned 90 degrees, kept prepare against a fresh one: relative RMS " << turnedAgree);
  CHECK(turnedAgree < 0.01);

  // The scale multiplies radiance; a frame-phase change as well.
  filter->SetEnvironmentScale(2);
  filter->Update();
  CHECK(filter->GetPrepareReused());
  const auto doubled = radianceOf(filter->GetOutput());
  for (std::size_t i = 0; i < doubled.size(); i += 17)
    CHECK(doubled[i].y == doctest::Approx(2 * turned[i].y).epsilon(1e-5));

  // A new material: prt's prepare integrates the profile, so it is rebuilt.
  filter->SetMaterial("marble");
  filter->Update();
  CHECK_FALSE(filter->GetPrepareReused());
  filter->Modified();  // run again, nothing changed: kept
  filter->Update();
  CHECK(filter->GetPrepareReused());
  sphere->SetThetaResolution(20);  // another surface
  filter->Update();
  CHECK_FALSE(filter->GetPrepareReused());
  filter->SetSizeMm(25);  // the same surface at another size
  filter->Update();
  CHECK_FALSE(filter->GetPrepareReused());
}

TEST_CASE(
    "vtkLucentFilter: an environment file that is missing or not an EXR is refused, naming it") {
  const lucent::test::TempDir dir;
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkLucentFilter> filter;
  filter->SetInputConnection(sphere->GetOutputPort());
  filter->SetSizeMm(300);  // where diffuse-brdf holds for skin: cheap
  filter->SetTechnique("diffuse-brdf");
  std::string error;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetClientData(&error);
  onError->SetCallback([](vtkObject*, unsigned long, void* self, void* text) {
    *static_cast<std::string*>(self) = text ? static_cast<const char*>(text) : "";
  });
  filter->AddObserver(vtkCommand::ErrorEvent, onError);
  vtkObject::GlobalWarningDisplayOn();  // VTK sends errors to observers only while this is on

  const std::string missing = dir / "no-such-sky.exr";
  filter->SetEnvironmentFileName(missing.c_str());
  filter->Update();
  CHECK(filter->GetOutput()->GetNumberOfPoints() == 0);
  CHECK(error.find(missing) != std::string::npos);
  CHECK(error.find("EnvironmentFileName") != std::string::npos);

  const std::string text = dir / "not-an-image.exr";
  std::ofstream(text) << "not an image\n";
  error.clear();
  filter->SetEnvironmentFileName(text.c_str());
  filter->Update();
  CHECK(filter->GetOutput()->GetNumberOfPoints() == 0);
  CHECK(error.find(text) != std::string::npos);

  // Back to the directional light: it runs again.
  error.clear();
  filter->SetEnvironmentFileName("");
  filter->Update();
  CHECK_MESSAGE(error.empty(), error);
  CHECK(filter->GetOutput()->GetNumberOfPoints() > 0);
}

TEST_CASE("vtkLucentFilter: an inner body's material or shape changed alone prepares again") {
  auto sphereOf = [](double radius) {
    vtkNew<vtkSphereSource> s;
    s->SetRadius(radius);
    s->SetThetaResolution(24);
    s->SetPhiResolution(12);
    s->Update();
    auto out = vtkSmartPointer<vtkPolyData>::New();
    out->DeepCopy(s->GetOutput());
    return out;
  };
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, sphereOf(4.0));
  auto inner = sphereOf(2.0);
  lucent::vtkadapter::markInnerBody(inner, "ketchup");
  blocks->SetBlock(1, inner);
  vtkNew<vtkLucentFilter> filter;
  filter->SetInputData(blocks);
  filter->SetMaterial("marble");
  filter->SetTechnique("taulut");
  filter->SetKnob("taulut.voxels", "16");
  filter->Update();
  REQUIRE(filter->GetOutput()->GetNumberOfPoints() > 0);
  filter->Modified();
  filter->Update();
  CHECK(filter->GetPrepareReused());  // nothing changed

  lucent::vtkadapter::markInnerBody(inner, "skin1");  // the same shape, another material
  blocks->Modified();
  filter->Update();
  CHECK_FALSE(filter->GetPrepareReused());

  auto smaller = sphereOf(1.5);  // the same material, another shape
  lucent::vtkadapter::markInnerBody(smaller, "skin1");
  blocks->SetBlock(1, smaller);
  filter->Update();
  CHECK_FALSE(filter->GetPrepareReused());
}
