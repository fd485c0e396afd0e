// One polydata-to-mesh conversion (vtk_plugin/Common/lucentPolyDataMesh.h) for the CLI's readers
// and the VTK filter: the same STL gives the same welded mesh and the same per-vertex radiosity
// through both.
#include <doctest/doctest.h>

#include <cmath>

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSTLWriter.h>
#include <vtkSphereSource.h>

#include "io/mesh_io.hpp"
#include "raycast/embree_ray_caster.hpp"
#include "technique/techniques.hpp"
#include "temp_dir.hpp"
#include "vtkLucentFilter.h"

TEST_CASE(
    "The same STL: one welded mesh and the same per-vertex radiosity through the CLI's reader and "
    "the filter") {
  lucent::test::TempDir dir;
  const std::string stl = dir / "sphere.stl";
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(10);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(16);
  vtkNew<vtkSTLWriter> writer;
  writer->SetInputConnection(sphere->GetOutputPort());
  writer->SetFileName(stl.c_str());
  REQUIRE(writer->Write() == 1);

  // The filter's input is the STL as stored: every triangle's corners apart (ParaView's reader can
  // give this).
  vtkNew<vtkSTLReader> raw;
  raw->SetFileName(stl.c_str());
  raw->MergingOff();
  raw->Update();
  REQUIRE(raw->GetOutput()->GetNumberOfPoints() == 3 * raw->GetOutput()->GetNumberOfPolys());
  vtkNew<vtkLucentFilter> filter;
  filter->SetInputConnection(raw->GetOutputPort());
  filter->SetMaterial("skin1");
  filter->SetLightDirection(1, 0.3, 0.4);
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  vtkDataArray* b = out->GetPointData()->GetArray("Radiosity");
  REQUIRE(b != nullptr);

  // The CLI's reader, and the same technique on the same vertices with the CLI's (Embree) ray
  // caster.
  namespace lt = lucent::technique;
  lt::SceneDescription scene;
  scene.mesh = lucent::io::readMesh(stl);
  REQUIRE(vtkIdType(scene.mesh.positions.size()) == out->GetNumberOfPoints());
  CHECK(scene.mesh.positions.size() ==
        std::size_t(sphere->GetOutput()->GetNumberOfPoints()));  // welded
  for (std::size_t i = 0; i < scene.mesh.positions.size(); ++i) {
    double p[3];
    out->GetPoint(vtkIdType(i), p);
    for (int k = 0; k < 3; ++k) REQUIRE(p[k] == doctest::Approx(scene.mesh.positions[i][k]));
  }
  scene.vertexNormals = scene.mesh.vertexNormals();
  scene.medium.material = *lucent::optics::findMaterial("skin1");
  scene.lights = {
      lucent::scene::DirectionalLight{glm::normalize(glm::dvec3(1, 0.3, 0.4)), glm::dvec3(1)}};
  const lucent::raycast::EmbreeRayCaster caster(scene.mesh);
  scene.caster = &caster;
  const auto& registry = lt::appRegistry();
  const auto& reference = registry.get("reference");
  const lt::Rendered cli =
      registry.render(reference, scene, reference.values(), lt::vertexRequest(scene.mesh));
  double d2 = 0, r2 = 0;
  for (std::size_t i = 0; i < cli.frame.radiosity.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double x = b->GetComponent(vtkIdType(i), c), y = cli.frame.radiosity[i][c];
      d2 += (x - y) * (x - y);
      r2 += y * y;
    }
  REQUIRE(r2 > 0);
  MESSAGE("filter vs CLI reader, per-vertex radiosity: relative RMS " << std::sqrt(d2 / r2));
  CHECK(std::sqrt(d2 / r2) < 1e-4);
}
