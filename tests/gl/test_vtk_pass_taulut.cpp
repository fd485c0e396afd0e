// vtkLucentPass's taulut twin (the voxel optical-thickness LUT on the GPU) as a VTK user runs it,
// headless under xvfb-run: per pixel against taulut on the CPU (the technique layer's, with Embree
// light-view maps) at the GPU's own pixel positions, for every storage and precision; a material
// edit against a fresh pass; the hard cases and bad knobs.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include <vtkCellArray.h>
#include <vtkOutputWindow.h>
#include <vtkPoints.h>
#include <vtkPolyDataMapper.h>

#include <lucent/optics/materials.hpp>
#include <lucent/scene/shapes.hpp>
#include <lucent/technique/core_techniques.hpp>

#include "cpu_agreement.hpp"
#include "pass_scene.hpp"
#include "raycast/embree_ray_caster.hpp"

namespace {
namespace lt = lucent::technique;
using lucent_test::Agreement;
using lucent_test::Frame;
using lucent_test::Inner;
using lucent_test::lastFrame;
using lucent_test::PassScene;

Agreement compareWithCpu(const lucent_test::Frame& f, const lucent::scene::TriangleMesh& world,
                         double sizeMm, const std::string& material, const glm::dvec3& towardLight,
                         const lt::KnobList& knobs, const std::vector<Inner>& inner = {}) {
  return lucent_test::compareWithCpu(f, world, sizeMm, material, towardLight, "taulut", knobs,
                                     inner);
}

using lucent::vtkadapter::polyDataOf;

void setKnobs(vtkLucentPass* pass, const lt::KnobList& knobs) {
  for (const auto& [name, value] : knobs) pass->SetKnob(("taulut." + name).c_str(), value.c_str());
}
}  // namespace

TEST_CASE(
    "vtkLucentPass taulut: per-pixel radiance matches taulut on the CPU on a cube with a cavity, "
    "for every storage and precision") {
  // A 5 mm (diagonal) marble cube with a spherical cavity, lit from behind and the side so light
  // crosses the cube around the cavity; the fixed tap pattern so both sides place the same taps.
  const auto world = lucent::scene::shapes::cubeWithCavity(0.6);
  const auto data = polyDataOf(world);
  const double toward[3] = {0.6, 0.5, -0.6};
  const double sizeMm = 5.0;
  PassScene scene(data, toward, 96);
  scene.pass->SetTechnique("taulut");
  scene.pass->SetMaterial("marble");
  scene.pass->SetSizeMm(sizeMm);
  const lt::KnobList common = {{"voxels", "16"}, {"map", "256"}, {"pattern", "fixed"}};
  for (const lt::KnobList& storage :
       {lt::KnobList{{"storage", "lut"}, {"precision", "fp32"}},
        lt::KnobList{{"storage", "lut"}, {"precision", "fp16"}}, lt::KnobList{{"storage", "march"}},
        lt::KnobList{{"storage", "hierarchical"}, {"cluster", "4"}}}) {
    lt::KnobList knobs = common;
    knobs.insert(knobs.end(), storage.begin(), storage.end());
    setKnobs(scene.pass, knobs);
    scene.render();
    INFO("storage " << storage.front().second
                    << ", error: " << std::string(scene.pass->GetLastError()));
    REQUIRE(scene.pass->GetTranslucentActorCount() == 1);
    const Frame f = lastFrame(scene.pass);
    REQUIRE(f.covered() > 1500);
    CHECK(f.allFiniteNonNegative());
    const Agreement a = compareWithCpu(f, world, sizeMm, "marble",
                                       glm::dvec3(toward[0], toward[1], toward[2]), knobs);
    lucent_test::checkAgreement(a,
                                "storage " + storage.front().second + " " + storage.back().second);
  }
}

TEST_CASE(
    "vtkLucentPass taulut: under a positional scene light it matches taulut on the CPU under "
    "the same point light") {
  // The cube with a cavity, a point light 4 units (a cube's side is 2) out along the same
  // direction: its irradiance falls off across the cube, and the map is framed along its axis.
  const auto world = lucent::scene::shapes::cubeWithCavity(0.6);
  const double toward[3] = {0.6, 0.5, -0.6};
  const double sizeMm = 5.0, distance = 4.0;
  PassScene scene(polyDataOf(world), toward, 96);
  scene.makePositional(toward, distance);
  scene.pass->SetTechnique("taulut");
  scene.pass->SetMaterial("marble");
  scene.pass->SetSizeMm(sizeMm);
  const lt::KnobList knobs = {{"voxels", "16"}, {"map", "256"}, {"pattern", "fixed"}};
  setKnobs(scene.pass, knobs);
  scene.render();
  INFO("error: " << std::string(scene.pass->GetLastError()));
  REQUIRE(scene.pass->GetTranslucentActorCount() == 1);
  const Frame f = lastFrame(scene.pass);
  REQUIRE(f.covered() > 1500);
  CHECK(f.allFiniteNonNegative());
  const glm::dvec3 w(toward[0], toward[1], toward[2]);
  const lucent::scene::PointLight point{distance * w,
                                        glm::dvec3(distance * distance * glm::dot(w, w))};
  lucent_test::checkAgreement(
      lucent_test::compareWithCpu(f, world, sizeMm, "marble", point, "taulut", knobs),
      "point light");
}

TEST_CASE(
    "vtkLucentPass taulut: an inner-body actor fills the actor around it with its material, as "
    "taulut on the CPU does") {
  // A 6 mm marble sphere holding a ketchup sphere of half its radius, back-lit from the side: the
  // light that reaches the camera crosses the ketchup.
  const auto outerWorld = lucent::scene::shapes::sphere(1.0, 5);
  const auto innerWorld = lucent::scene::shapes::sphere(0.5, 4, glm::dvec3(0.1, 0, 0));
  const double toward[3] = {0.8, 0.2, -0.6};
  PassScene scene(polyDataOf(outerWorld), toward, 96);
  vtkNew<vtkPolyDataMapper> innerMapper;
  const auto innerData = polyDataOf(innerWorld);
  lucent::vtkadapter::markInnerBody(innerData, "ketchup");
  innerMapper->SetInputData(innerData);
  vtkNew<vtkActor> innerActor;
  innerActor->SetMapper(innerMapper);
  scene.renderer->AddActor(innerActor);
  scene.pass->SetTechnique("taulut");
  scene.pass->SetMaterial("marble");
  scene.pass->SetSizeMm(6);
  const lt::KnobList knobs = {{"voxels", "20"}, {"map", "256"}, {"pattern", "fixed"}};
  setKnobs(scene.pass, knobs);
  scene.render();
  INFO(std::string(scene.pass->GetLastError()));
  REQUIRE(scene.pass->GetTranslucentActorCount() == 1);  // the inner body is not shaded itself
  const Frame withInner = lastFrame(scene.pass);
  REQUIRE(withInner.covered() > 1500);
  const glm::dvec3 light(toward[0], toward[1], toward[2]);
  const Agreement a =
      compareWithCpu(withInner, outerWorld, 6, "marble", light, knobs, {{innerWorld, "ketchup"}});
  lucent_test::checkAgreement(a, "with a ketchup inner body");
  // Without it (the actor hidden), the sphere is marble throughout: a different image.
  innerActor->VisibilityOff();
  scene.render();
  const Frame without = lastFrame(scene.pass);
  double sumWith = 0, sumWithout = 0;
  for (std::size_t i = 0; i < without.radiance.size(); i += 4)
    sumWith += withInner.radiance[i + 1], sumWithout += without.radiance[i + 1];
  MESSAGE("green radiance summed: with the ketchup " << sumWith << ", all marble " << sumWithout);
  // taulut sees extinction only, and ketchup's sigma_a + sigma_s' is below marble's in every
  // channel (green: 1.04 against 2.62 per mm): light crosses the middle more easily.
  CHECK(sumWith > 1.02 * sumWithout);
}

TEST_CASE("vtkLucentPass taulut: a material edit gives what a fresh pass gives") {
  const auto data = polyDataOf(lucent::scene::shapes::cubeWithCavity(0.6));
  const double toward[3] = {0.3, 0.8, -0.5};
  PassScene edited(data, toward, 64), fresh(data, toward, 64);
  for (PassScene* s : {&edited, &fresh}) {
    s->pass->SetTechnique("taulut");
    s->pass->SetSizeMm(5);
    setKnobs(s->pass, {{"voxels", "12"}, {"map", "128"}});
  }
  edited.pass->SetMaterial("skin1");
  edited.render();
  const Frame skin = lastFrame(edited.pass);
  edited.pass->SetMaterial(
      "ketchup");  // the table is per-medium lengths: nothing is prepared again
  edited.render();
  fresh.pass->SetMaterial("ketchup");
  fresh.render();
  const Frame a = lastFrame(edited.pass), b = lastFrame(fresh.pass);
  REQUIRE(a.covered() > 500);
  CHECK(a.radiance == b.radiance);
  CHECK(a.radiance != skin.radiance);  // the edit reached the frame
}

TEST_CASE("vtkLucentPass taulut: hard cases stay finite, bad knobs are reported, not crashed on") {
  const double side[3] = {1.0, 0.5, 0.5};
  const auto data = lucent_test::sphere(1.0, 48);
  PassScene scene(data, side, 64);
  scene.pass->SetTechnique("taulut");
  setKnobs(scene.pass, {{"voxels", "10"}, {"map", "128"}});
  SUBCASE("zero absorption, a 1 um and a 1 m object, one voxel a side too few") {
    for (const auto& [material, size] : lucent_test::kHardMaterialSizes) {
      scene.pass->SetMaterial(material);
      scene.pass->SetSizeMm(size);
      scene.render();
      INFO(material << " at " << size << " mm: " << std::string(scene.pass->GetLastError()));
      CHECK(scene.pass->GetTranslucentActorCount() == 1);
      const Frame f = lastFrame(scene.pass);
      CHECK(f.covered() > 500);
      CHECK(f.allFiniteNonNegative());
    }
  }
  SUBCASE("a bad choice names the choices; a table over the bound names the fix") {
    vtkOutputWindow::GetInstance()->SetDisplayModeToNever();  // the errors are expected here
    scene.pass->SetKnob("taulut.storage", "zip");
    scene.render();
    std::string error = scene.pass->GetLastError();
    CHECK(error.find("zip") != std::string::npos);
    CHECK(error.find("hierarchical") != std::string::npos);
    setKnobs(scene.pass, {{"storage", "lut"}, {"voxels", "60"}, {"max-table-mb", "1"}});
    scene.render();
    error = scene.pass->GetLastError();
    CHECK(error.find("MiB bound") != std::string::npos);
    CHECK(error.find("storage=hierarchical") != std::string::npos);
    scene.pass->SetTechnique("quadgraph");
    scene.render();
    error = scene.pass->GetLastError();
    CHECK(error.find("no GPU twin") != std::string::npos);
    CHECK(error.find("taulut") != std::string::npos);
    vtkOutputWindow::GetInstance()->SetDisplayModeToDefault();
  }
}
