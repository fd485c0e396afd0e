// What the pass's GL tests share: one actor under one directional light with the pass around
// VTK's render steps, and the frame the pass kept.
#pragma once

#include <cmath>
#include <utility>
#include <vector>

#include <doctest/doctest.h>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

#include "lucentPolyDataMesh.h"
#include "vtkLucentPass.h"

namespace lucent_test {
/// One actor, one directional scene light, a camera on +z, the pass around VTK's render steps.
struct PassScene {
  vtkNew<vtkPolyDataMapper> mapper;
  vtkNew<vtkActor> actor;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkLight> light;
  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkLucentPass> pass;
  vtkNew<vtkRenderWindow> window;
  int width, height;

  PassScene(vtkPolyData* data, const double towardLight[3], int size) : width(size), height(size) {
    mapper->SetInputData(data);
    actor->SetMapper(mapper);
    actor->GetProperty()->SetDiffuse(0.0);
    renderer->AddActor(actor);
    light->SetLightTypeToSceneLight();
    light->PositionalOff();
    light->SetFocalPoint(0, 0, 0);
    light->SetPosition(towardLight);
    renderer->AddLight(light);
    pass->SetDelegatePass(steps);
    pass->KeepFrameOn();
    renderer->SetPass(pass);
    window->SetOffScreenRendering(1);
    window->AddRenderer(renderer);
    window->SetSize(size, size);
    renderer->GetActiveCamera()->SetPosition(0, 0, 1);
    renderer->GetActiveCamera()->SetFocalPoint(0, 0, 0);
    renderer->ResetCamera();
  }
  void render() { window->Render(); }
  /// The scene light made a point light at `distance` times its direction from the origin (its
  /// focal point, where its irradiance is 1).
  void makePositional(const double towardLight[3], double distance) {
    light->PositionalOn();
    light->SetConeAngle(90);  // a spotlight cone only limits VTK's own shading
    light->SetPosition(distance * towardLight[0], distance * towardLight[1],
                       distance * towardLight[2]);
  }
  /// The final image, RGB bytes.
  std::vector<unsigned char> pixels() {
    vtkNew<vtkUnsignedCharArray> rgb;
    window->GetPixelData(0, 0, width - 1, height - 1, 0, rgb);
    return std::vector<unsigned char>(rgb->GetPointer(0), rgb->GetPointer(0) + 3 * width * height);
  }
};

/// The hard cases of a twin: zero absorption (spectralon), a 1 um and a 1 nm object, a 1 m one
/// (material, diagonal in mm).
inline constexpr std::pair<const char*, double> kHardMaterialSizes[] = {
    {"spectralon", 20.0}, {"skin1", 1e-3}, {"marble", 1e3}, {"ketchup", 1e-6}};

inline vtkSmartPointer<vtkPolyData> sphere(double radius, int resolution) {
  vtkNew<vtkSphereSource> source;
  source->SetRadius(radius);
  source->SetThetaResolution(resolution);
  source->SetPhiResolution(resolution / 2);
  source->Update();
  return source->GetOutput();
}

/// The mesh the pass itself builds from the data (the one conversion, lucentPolyDataMesh.h).
inline lucent::scene::TriangleMesh toMesh(vtkPolyData* data) {
  return lucent::vtkadapter::meshFromData(data).mesh;
}

struct Frame {
  int width = 0, height = 0;
  std::vector<float> radiance, position, normal;
  std::size_t covered() const {
    std::size_t n = 0;
    for (std::size_t i = 3; i < radiance.size(); i += 4) n += radiance[i] > 0;
    return n;
  }
  bool allFiniteNonNegative() const {
    for (std::size_t i = 0; i < radiance.size(); ++i)
      if (!std::isfinite(radiance[i]) || radiance[i] < 0) return false;
    return true;
  }
};

inline Frame lastFrame(vtkLucentPass* pass) {
  Frame f;
  REQUIRE(pass->GetLastFrame(f.width, f.height, f.radiance, f.position, f.normal));
  return f;
}
}  // namespace lucent_test
