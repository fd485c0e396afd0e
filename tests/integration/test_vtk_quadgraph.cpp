// Lucent::QuadGraph: the AGPL technique offered in vtkLucentFilter by its own module, checked
// against the dipole sum (the reference technique) on the same vertices.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>

#include "vtkLucentFilter.h"
#include "vtkLucentQuadGraph.h"

namespace {
std::vector<double> radiosity(vtkLucentFilter* filter) {
  filter->Update();
  vtkDataArray* b = filter->GetOutput()->GetPointData()->GetArray("Radiosity");
  REQUIRE(b != nullptr);
  std::vector<double> v;
  for (vtkIdType i = 0; i < b->GetNumberOfTuples(); ++i)
    for (int c = 0; c < 3; ++c) v.push_back(b->GetComponent(i, c));
  return v;
}
}  // namespace

TEST_CASE(
    "vtkLucentFilter offers quadgraph through Lucent::QuadGraph, per vertex it agrees with the "
    "dipole sum") {
  REQUIRE(vtkLucentQuadGraph::Register());
  bool offered = false;
  for (int i = 0; i < vtkLucentFilter::GetNumberOfTechniques(); ++i)
    offered |= vtkLucentFilter::GetTechniqueName(i) == "quadgraph";
  CHECK(offered);

  // A 20 mm marble sphere lit from the side: high albedo, where diffusion and the dipole agree
  // best.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(10);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  auto run = [&](const char* technique) {
    vtkNew<vtkLucentFilter> filter;
    filter->SetInputConnection(sphere->GetOutputPort());
    filter->SetMaterial("marble");
    filter->SetLightDirection(1, 0.3, 0.4);
    filter->SetTechnique(technique);
    filter->SetKnob("quadgraph.levels", "1");
    return radiosity(filter);
  };
  const auto reference = run("reference"), diffusion = run("quadgraph");
  REQUIRE(diffusion.size() == reference.size());
  for (int c = 0; c < 3; ++c) {
    double d2 = 0, r2 = 0, sd = 0, sr = 0;
    for (std::size_t i = std::size_t(c); i < reference.size(); i += 3) {
      REQUIRE(std::isfinite(diffusion[i]));
      REQUIRE(diffusion[i] >= 0);
      d2 += (diffusion[i] - reference[i]) * (diffusion[i] - reference[i]);
      r2 += reference[i] * reference[i];
      sd += diffusion[i], sr += reference[i];
    }
    MESSAGE("channel " << c << ": quadgraph / dipole mean " << sd / sr << ", relative RMS "
                       << std::sqrt(d2 / r2));
    // Against the path tracer (docs/accuracy/quadgraph.md, marble 30 mm) QuadGraph gives 1.03-1.04
    // and the dipole 0.93: their ratio, 1.11, is what the two should show here too.
    CHECK(sd / sr == doctest::Approx(1.11).epsilon(0.05));
    CHECK(std::sqrt(d2 / r2) < 0.2);
  }
}
