// vtkLucentFilter (vtk_plugin/Filters) as a VTK user runs it: on a source, in a pipeline, headless.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>
#include <vtkTessellatedBoxSource.h>
#include <vtkTriangleFilter.h>

#include "vtkLucentFilter.h"

namespace {
// Jensen et al. 2001, Eq. 6 totalled over the plane (their total diffuse reflectance), typed in from the
// paper: Rd = (alpha'/2) (1 + exp(-(4/3) A sqrt(3 (1 - alpha')))) exp(-sqrt(3 (1 - alpha'))).
double totalDiffuseReflectance(double sigmaA, double sigmaSPrime, double eta) {
  const double alpha = sigmaSPrime / (sigmaA + sigmaSPrime);
  const double fdr = -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta, a = (1 + fdr) / (1 - fdr);
  const double s = std::sqrt(3 * (1 - alpha));
  return 0.5 * alpha * (1 + std::exp(-4.0 / 3.0 * a * s)) * std::exp(-s);
}
}  // namespace

TEST_CASE("vtkLucentFilter: a lit slab's face matches the dipole's total diffuse reflectance; shadowed side dark; progress") {
  // A 60 x 60 x 30 mm box of skin, lit from +z with irradiance 2: far from the edges, the top face is a
  // half-space, where B = Ft(0) E Rd_total (Rd integrated over the plane).
  vtkNew<vtkTessellatedBoxSource> box;
  box->SetBounds(-30, 30, -30, 30, -15, 15);
  box->SetLevel(24);
  box->QuadsOn();
  vtkNew<vtkLucentFilter> filter;
  filter->SetInputConnection(box->GetOutputPort());
  filter->SetMaterial("skin1");
  filter->SetLightDirection(0, 0, 1);
  filter->SetLightIrradiance(2.0);
  filter->SetSampleFraction(1.0);
  int progressEvents = 0;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progressEvents);
  onProgress->SetCallback([](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
  filter->AddObserver(vtkCommand::ProgressEvent, onProgress);
  filter->Update();

  vtkPolyData* out = filter->GetOutput();
  vtkDataArray* b = out->GetPointData()->GetArray("Radiosity");
  REQUIRE(b != nullptr);
  REQUIRE(out->GetPointData()->GetScalars() != nullptr);
  CHECK(std::string(out->GetPointData()->GetScalars()->GetName()) == "TranslucentColor");
  CHECK(progressEvents >= 10);
  CHECK(filter->GetSampleCount() > 1000);

  const double sigmaA[3] = {0.032, 0.17, 0.48}, sigmaSPrime[3] = {0.74, 0.88, 1.01}, eta = 1.3;
  const double ft0 = 1 - std::pow((eta - 1) / (eta + 1), 2);
  int centre = 0, bottom = 0;
  double topMean[3] = {0, 0, 0}, bottomMax[3] = {0, 0, 0};
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
    double p[3];
    out->GetPoint(i, p);
    for (int c = 0; c < 3; ++c) REQUIRE(std::isfinite(b->GetComponent(i, c)));
    if (std::abs(p[2] - 15) < 1e-9 && std::hypot(p[0], p[1]) < 6) {
      ++centre;
      for (int c = 0; c < 3; ++c) {
        INFO("channel " << c << " at " << p[0] << ", " << p[1]);
        CHECK(b->GetComponent(i, c) == doctest::Approx(2 * ft0 * totalDiffuseReflectance(sigmaA[c], sigmaSPrime[c], eta)).epsilon(0.03));
        topMean[c] += b->GetComponent(i, c);
      }
    }
    if (std::abs(p[2] + 15) < 1e-9 && std::hypot(p[0], p[1]) < 6) {
      ++bottom;
      for (int c = 0; c < 3; ++c) bottomMax[c] = std::max(bottomMax[c], b->GetComponent(i, c));
    }
  }
  REQUIRE(centre >= 4);
  CHECK(bottom >= 4);
  // The shadowed face, 30 mm of skin away from any lit point, is dark: red (diffusion length 3.7 mm) passes
  // about e^-8 of the light, blue nothing.
  for (int c = 0; c < 3; ++c) CHECK(bottomMax[c] < 1e-3 * topMean[c] / centre);
}

TEST_CASE("vtkLucentFilter: tiny, huge and eta-extreme inputs stay finite; bad input is an error, not a crash") {
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(12);
  for (double size : {0.001, 1000.0}) {
    vtkNew<vtkLucentFilter> filter;
    filter->SetInputConnection(sphere->GetOutputPort());
    filter->SetSizeMm(size);
    filter->SetMaterial(size < 1 ? "spectralon" : "ketchup");
    filter->SetMaxSamples(20000);
    filter->Update();
    vtkDataArray* b = filter->GetOutput()->GetPointData()->GetArray("Radiosity");
    REQUIRE(b != nullptr);
    double lit = 0;
    for (vtkIdType i = 0; i < b->GetNumberOfTuples(); ++i)
      for (int c = 0; c < 3; ++c) {
        REQUIRE(std::isfinite(b->GetComponent(i, c)));
        REQUIRE(b->GetComponent(i, c) >= 0);
        lit = std::max(lit, b->GetComponent(i, c));
      }
    CHECK(lit > 0);
  }

  // An unknown material and an input without polygons: error, empty output, no crash.
  vtkNew<vtkLucentFilter> bad;
  bad->SetInputConnection(sphere->GetOutputPort());
  bad->SetMaterial("unobtainium");
  bad->GlobalWarningDisplayOff();
  bad->Update();
  CHECK(bad->GetOutput()->GetNumberOfPoints() == 0);
  vtkNew<vtkPolyData> empty;
  bad->SetInputData(empty);
  bad->SetMaterial("skin1");
  bad->Update();
  CHECK(bad->GetOutput()->GetNumberOfPoints() == 0);
}

TEST_CASE("vtkLucentFilter: the TSIS technique matches the reference per vertex and converges in N") {
  // A 20 mm skin sphere lit from the side: TSIS (atlas irradiance, mip-ICDF samples, Eq. 10) against
  // the dense dipole sum, vertex by vertex (relative RMS over the vertices, as docs/ reports errors).
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(10);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  auto run = [&](int technique, int samples) {
    vtkNew<vtkLucentFilter> filter;
    filter->SetInputConnection(sphere->GetOutputPort());
    filter->SetMaterial("skin1");
    filter->SetLightDirection(1, 0.3, 0.4);
    filter->SetTechnique(technique);
    filter->SetTsisSamples(samples);
    filter->SetAtlasResolution(512);
    filter->Update();
    vtkDataArray* b = filter->GetOutput()->GetPointData()->GetArray("Radiosity");
    REQUIRE(b != nullptr);
    std::vector<double> values(std::size_t(3 * b->GetNumberOfTuples()));
    for (vtkIdType i = 0; i < b->GetNumberOfTuples(); ++i)
      for (int c = 0; c < 3; ++c) values[std::size_t(3 * i + c)] = b->GetComponent(i, c);
    return values;
  };
  const auto reference = run(vtkLucentFilter::Reference, 0);
  double error[2][3];
  const int counts[2] = {1024, 8192};
  for (int k = 0; k < 2; ++k) {
    const auto tsis = run(vtkLucentFilter::TSIS, counts[k]);
    REQUIRE(tsis.size() == reference.size());
    for (int c = 0; c < 3; ++c) {
      double d2 = 0, r2 = 0;
      for (std::size_t i = std::size_t(c); i < tsis.size(); i += 3) {
        REQUIRE(std::isfinite(tsis[i]));
        d2 += (tsis[i] - reference[i]) * (tsis[i] - reference[i]);
        r2 += reference[i] * reference[i];
      }
      error[k][c] = std::sqrt(d2 / r2);
      MESSAGE("TSIS N = " << counts[k] << ", channel " << c << ": relative RMS against the reference " << error[k][c]);
    }
  }
  for (int c = 0; c < 3; ++c) CHECK(error[1][c] < 0.05);
  CHECK(error[1][2] < error[0][2] / 1.4);
}
