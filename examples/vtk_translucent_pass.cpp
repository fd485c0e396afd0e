// A VTK program turns on translucent rendering with one render pass: vtkLucentPass around VTK's usual
// render steps. Every opaque surface becomes skin (or another measured material), lit by the scene's
// light; here the light is behind the object, so thin parts glow. With --sweep it prints the frame time
// for several sample counts (the accuracy / time knob of the GPU path).
//
//   build/examples/vtk_translucent_pass [OUT.png] [--size PX] [--samples N] [--sweep]
//   (needs a display or xvfb-run -a)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSuperquadricSource.h>
#include <vtkWindowToImageFilter.h>

#include "vtkLucentPass.h"

int main(int argc, char** argv) {
  std::string out = "translucent-pass.png";
  int size = 512, samples = 1024;
  bool sweep = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--size" && i + 1 < argc) size = std::atoi(argv[++i]);
    else if (a == "--samples" && i + 1 < argc) samples = std::atoi(argv[++i]);
    else if (a == "--sweep") sweep = true;
    else out = a;
  }

  vtkNew<vtkSuperquadricSource> shape;  // a torus-like superquadric with thin and thick parts
  shape->ToroidalOn();
  shape->SetThickness(0.35);
  shape->SetThetaResolution(96);
  shape->SetPhiResolution(48);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(shape->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetDiffuse(0.0);  // the pass supplies the diffuse (subsurface) part
  actor->GetProperty()->SetSpecular(0.4);
  actor->GetProperty()->SetSpecularPower(40);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.05, 0.05, 0.07);
  renderer->GetActiveCamera()->SetPosition(0, 0.6, 1);
  renderer->GetActiveCamera()->SetViewUp(0, 1, 0);
  renderer->ResetCamera();
  vtkNew<vtkLight> backLight;  // behind the object, as seen from the camera
  backLight->SetLightTypeToSceneLight();
  backLight->SetPosition(0.3, 0.9, -1.0);
  backLight->SetFocalPoint(0, 0, 0);
  backLight->PositionalOff();
  renderer->AddLight(backLight);

  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkLucentPass> lucent;
  lucent->SetDelegatePass(steps);
  lucent->SetMaterial("skin1");
  lucent->SetSizeMm(30);  // the object's bounding-box diagonal is 30 mm
  lucent->SetSamples(samples);
  lucent->SetExposure(12);  // L = Ft B / pi: about pi times darker than the filter's B at the same exposure
  renderer->SetPass(lucent);

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(size, size);
  window->Render();
  if (lucent->GetTranslucentActorCount() != 1) {
    std::fprintf(stderr, "vtk_translucent_pass: nothing was shaded: %s\n", lucent->GetLastError());
    return 1;
  }
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  vtkNew<vtkPNGWriter> png;
  png->SetFileName(out.c_str());
  png->SetInputConnection(grab->GetOutputPort());
  png->Write();
  std::printf("%s, %d samples, %dx%d: wrote %s\n", lucent->GetMaterial(), samples, size, size, out.c_str());

  if (sweep) {
    // Each frame redoes every stage (the light or the object may move); the camera orbits to defeat caching.
    std::printf("%8s %12s %12s\n", "samples", "ms/frame", "frames/s");
    for (int n : {16, 64, 256, 1024}) {
      lucent->SetSamples(n);
      window->Render();  // warm-up: shader compile, atlas
      const int frames = 5;
      const auto start = std::chrono::steady_clock::now();
      for (int f = 0; f < frames; ++f) {
        renderer->GetActiveCamera()->Azimuth(2);
        window->Render();
      }
      window->WaitForCompletion();
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / frames;
      std::printf("%8d %12.1f %12.2f\n", n, ms, 1000.0 / ms);
    }
  }
  return 0;
}
