// A VTK program turns on translucent rendering with one render pass: vtkLucentPass around VTK's
// usual render steps. Every opaque surface becomes skin (or another measured material), lit by the
// scene's light; here the light is behind the object, so thin parts glow. --technique picks the GPU
// twin (tsis, the default, hybrid, taulut or diffuse-brdf), --knob sets its knobs; with --sweep it
// prints the frame time over the technique's own default sweep (`lucent techniques` lists it) or
// the given one, the accuracy / time knob of the GPU path, with the per-pixel sum's rate and a
// linear fit of the frame time. --shape cube-cavity renders the cube with a spherical cavity of
// Mochida et al. 2016.
//
//   build/examples/vtk_translucent_pass [OUT.png] [--size PX] [--technique NAME] [--material NAME]
//       [--knob NAME=VALUE]... [--shape torus|cube-cavity] [--size-mm MM] [--sweep] [--frames N]
//   (needs a display or xvfb-run -a)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

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

#include <lucent/technique/registry.hpp>
#include "technique/core_registry.hpp"  // the registry lucent_app compiled (a minute per unit that builds it)
#include "scene/builtin_shapes.hpp"

#include "lucentPolyDataMesh.h"
#include "vtkLucentPass.h"

namespace {
struct Options {
  std::string out = "translucent-pass.png", technique = "tsis", material = "skin1",
              shape = "superquadric", fill;
  int size = 512, frames = 5;
  double sizeMm = 30;
  bool sweep = false;
  std::string sweepSpec;  ///< KNOB=V1,V2,...; empty: the technique's default sweep
  std::vector<std::pair<std::string, std::string>> knobs;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool more = i + 1 < argc;
    if (a == "--size" && more)
      o.size = std::atoi(argv[++i]);
    else if (a == "--frames" && more)
      o.frames = std::max(1, std::atoi(argv[++i]));
    else if (a == "--technique" && more)
      o.technique = argv[++i];
    else if (a == "--material" && more)
      o.material = argv[++i];
    else if (a == "--shape" && more)
      o.shape = argv[++i];
    else if (a == "--fill" && more)
      o.fill = argv[++i];
    else if (a == "--size-mm" && more)
      o.sizeMm = std::atof(argv[++i]);
    else if (a == "--sweep") {
      o.sweep = true;
      if (more && std::string(argv[i + 1]).find('=') != std::string::npos) o.sweepSpec = argv[++i];
    } else if (a == "--knob" && more) {
      const std::string kv = argv[++i];
      const auto eq = kv.find('=');
      if (eq == std::string::npos) {
        std::fprintf(stderr, "vtk_translucent_pass: --knob %s: give NAME=VALUE\n", kv.c_str());
        std::exit(2);
      }
      o.knobs.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
    } else
      o.out = a;
  }
  return o;
}

/// The torus-like superquadric (thin and thick parts), or one of lucent's built-in shapes.
vtkSmartPointer<vtkPolyData> shapeOf(const std::string& name) {
  if (name != "superquadric")
    return lucent::vtkadapter::polyDataOf(lucent::scene::makeBuiltinShape(name));
  vtkNew<vtkSuperquadricSource> shape;
  shape->ToroidalOn();
  shape->SetThickness(0.35);
  shape->SetThetaResolution(96);
  shape->SetPhiResolution(48);
  shape->Update();
  return shape->GetOutput();
}

/// The shape's inner bodies (the bottle's liquid) as actors whose data is marked as such.
void addInnerBodies(const Options& o, vtkRenderer* renderer) {
  if (o.shape == "superquadric") return;
  for (const auto& body : lucent::scene::builtinInnerBodies(o.shape)) {
    auto data = lucent::vtkadapter::polyDataOf(body.surface);
    lucent::vtkadapter::markInnerBody(data, o.fill.empty() ? body.defaultMaterial : o.fill);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(data);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    renderer->AddActor(actor);
  }
}

/// Milliseconds per frame: each frame redoes every per-frame stage (the light or the object may
/// move); the camera orbits to defeat caching. The first frame (shaders, prepare) is not counted.
double frameMs(vtkRenderWindow* window, vtkRenderer* renderer, int frames) {
  window->Render();
  const auto start = std::chrono::steady_clock::now();
  for (int f = 0; f < frames; ++f) {
    renderer->GetActiveCamera()->Azimuth(2);
    window->Render();
  }
  window->WaitForCompletion();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
             .count() /
         frames;
}

/// The "OpenGL renderer string" line of the window's capabilities (llvmpipe, or the GPU).
std::string glRenderer(vtkRenderWindow* window) {
  const std::string caps = window->ReportCapabilities();
  const auto at = caps.find("OpenGL renderer string");
  return at == std::string::npos ? "OpenGL renderer unknown"
                                 : caps.substr(at, caps.find('\n', at) - at);
}

/// Pixels the pass shaded translucent in one frame (a frame kept for the count, then not).
std::size_t translucentPixels(vtkRenderWindow* window, vtkLucentPass* pass) {
  pass->KeepFrameOn();
  window->Render();
  pass->KeepFrameOff();
  int width = 0, height = 0;
  std::vector<float> radiance, position, normal;
  if (!pass->GetLastFrame(width, height, radiance, position, normal)) return 0;
  std::size_t n = 0;
  for (std::size_t i = 3; i < radiance.size(); i += 4) n += radiance[i] > 0;
  return n;
}

/// Frame time against a numeric knob: ms = fixed + slope x value by least squares (the per-pixel
/// sum grows with samples; the atlas, sampling and composite do not).
void printFit(const std::vector<std::pair<double, double>>& valueMs, const std::string& knob) {
  if (valueMs.size() < 2) return;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = double(valueMs.size());
  for (const auto& [x, y] : valueMs) sx += x, sy += y, sxx += x * x, sxy += x * y;
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  std::printf("fit: ms/frame = %.2f + %.5f x %s\n", (sy - slope * sx) / n, slope, knob.c_str());
}

/// One sweep: ms per frame at each value and, for samples, the per-pixel sum's rate (pixel-sample
/// terms per second over the translucent pixels).
void runSweep(vtkRenderWindow* window, vtkRenderer* renderer, vtkLucentPass* lucent,
              const std::string& technique, const lucent::technique::Sweep& sweep, int frames) {
  const std::size_t pixels = translucentPixels(window, lucent);
  std::printf("%s over %zu translucent pixels\n", technique.c_str(), pixels);
  std::printf("%14s %12s %12s %16s\n", sweep.knob.c_str(), "ms/frame", "frames/s",
              "pixel-samples/s");
  std::vector<std::pair<double, double>> valueMs;
  for (const auto& value : sweep.values) {
    const std::string name = technique + "." + sweep.knob;
    lucent->SetKnob(name.c_str(), value.c_str());
    const double ms = frameMs(window, renderer, frames);
    const std::string used = lucent->GetKnob(name.c_str());
    const double x = std::atof(used.c_str());
    valueMs.emplace_back(x, ms);
    const double rate = sweep.knob == "samples" ? double(pixels) * x / (ms / 1000) : 0.0;
    std::printf("%14s %12.1f %12.2f %16.3g\n", used.c_str(), ms, 1000.0 / ms, rate);
  }
  printFit(valueMs, sweep.knob);
}
}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(shapeOf(o.shape));
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetDiffuse(0.0);  // the pass supplies the diffuse (subsurface) part
  actor->GetProperty()->SetSpecular(0.4);
  actor->GetProperty()->SetSpecularPower(40);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  addInnerBodies(o, renderer);
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
  lucent->SetTechnique(o.technique.c_str());
  lucent->SetMaterial(o.material.c_str());
  lucent->SetSizeMm(o.sizeMm);  // the object's bounding-box diagonal
  if (o.technique == "tsis") lucent->SetSamples(1024);
  for (const auto& [name, value] : o.knobs)
    lucent->SetKnob((o.technique + "." + name).c_str(), value.c_str());
  lucent->SetExposure(12);  // L = Ft B / pi: about pi times darker than the filter's B
  renderer->SetPass(lucent);

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(o.size, o.size);
  const auto prepareStart = std::chrono::steady_clock::now();
  window->Render();
  const double firstMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - prepareStart)
          .count();
  if (lucent->GetTranslucentActorCount() != 1) {
    std::fprintf(stderr, "vtk_translucent_pass: nothing was shaded: %s\n", lucent->GetLastError());
    return 1;
  }
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  vtkNew<vtkPNGWriter> png;
  png->SetFileName(o.out.c_str());
  png->SetInputConnection(grab->GetOutputPort());
  png->Write();
  std::printf("%s, %s, %dx%d: wrote %s (first frame, with prepare: %.0f ms)\n", o.technique.c_str(),
              lucent->GetMaterial(), o.size, o.size, o.out.c_str(), firstMs);

  if (o.sweep) {
    const auto registry = lucent::technique::compiledCoreRegistry();
    const lucent::technique::Technique& t = registry.get(o.technique);
    std::vector<lucent::technique::Sweep> sweeps = t.defaultSweep;
    if (!o.sweepSpec.empty()) {
      const auto eq = o.sweepSpec.find('=');
      lucent::technique::Sweep given{o.sweepSpec.substr(0, eq), {}};
      std::stringstream values(o.sweepSpec.substr(eq + 1));
      for (std::string v; std::getline(values, v, ',');) given.values.push_back(v);
      sweeps = {given};
    }
    std::printf("%s\n", glRenderer(window).c_str());
    for (const auto& sweep : sweeps) runSweep(window, renderer, lucent, t.name, sweep, o.frames);
  }
  return 0;
}
