// A VTK program adds one filter to make a surface translucent: vtkLucentFilter between a source and its
// mapper, the per-vertex colour shown as is (lighting off: the filter's radiosity already is the shading).
// A back light makes the thin parts glow.
//
//   build/examples/vtk_translucent_filter [OUT.png]   (default translucent-filter.png; needs a display or xvfb-run -a)
#include <cstdio>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSuperquadricSource.h>
#include <vtkWindowToImageFilter.h>

#include "vtkLucentFilter.h"

int main(int argc, char** argv) {
  const char* out = argc > 1 ? argv[1] : "translucent-filter.png";
  vtkNew<vtkSuperquadricSource> shape;  // a torus-like superquadric with thin and thick parts
  shape->ToroidalOn();
  shape->SetThickness(0.35);
  shape->SetThetaResolution(96);
  shape->SetPhiResolution(48);

  vtkNew<vtkLucentFilter> translucent;
  translucent->SetInputConnection(shape->GetOutputPort());
  translucent->SetMaterial("skin1");
  translucent->SetSizeMm(30);                      // the data's bounding-box diagonal becomes 30 mm
  translucent->SetLightDirection(0.3, 0.9, -1.0);  // behind the object, as seen from the camera below
  translucent->SetExposure(4);

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(translucent->GetOutputPort());
  mapper->SetColorModeToDirectScalars();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0, 0, 0);
  renderer->GetActiveCamera()->SetPosition(0, 0.6, 1);
  renderer->GetActiveCamera()->SetViewUp(0, 1, 0);
  renderer->ResetCamera();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(400, 400);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  vtkNew<vtkPNGWriter> png;
  png->SetFileName(out);
  png->SetInputConnection(grab->GetOutputPort());
  png->Write();
  std::printf("%s: %lld surface samples, wrote %s\n", translucent->GetMaterial(),
              static_cast<long long>(translucent->GetSampleCount()), out);
  return 0;
}
