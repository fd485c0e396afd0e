// vtkLucentVolumeFilter (vtk_plugin/Filters): a scan as a translucent object, as a VTK user runs
// it. A transfer function that is one coefficient pair everywhere, and a scan of one constant
// value, must shade the isosurface as vtkLucentFilter shades it with the material those
// coefficients are; label maps and bad input are checked by their own outcomes.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <glm/geometric.hpp>

#include <lucent/optics/materials.hpp>

#include "lucentScanSurface.h"
#include "vtkLucentFilter.h"
#include "vtkLucentVolumeFilter.h"

namespace {
/// A 2 mm-spaced scan, anisotropic in z (3 mm), of `f(x)` at the voxel centres, x in mm from the
/// scan's centre.
template <class F>
vtkSmartPointer<vtkImageData> scan(int n, const F& f, const char* name = "density") {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  const double spacing[3] = {2, 2, 3};
  image->SetSpacing(spacing);
  image->SetOrigin(-spacing[0] * (n - 1) / 2, -spacing[1] * (n - 1) / 2, -spacing[2] * (n - 1) / 2);
  vtkNew<vtkFloatArray> values;
  values->SetName(name);
  values->SetNumberOfTuples(vtkIdType(n) * n * n);
  for (vtkIdType id = 0; id < values->GetNumberOfTuples(); ++id) {
    double p[3];
    image->GetPoint(id, p);
    values->SetValue(id, float(f(glm::dvec3(p[0], p[1], p[2]))));
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

/// A sphere of radius 12 mm: the value is 12 - |x| (positive inside).
vtkSmartPointer<vtkImageData> sphereScan() {
  return scan(16, [](const glm::dvec3& x) { return 12.0 - glm::length(x); });
}

std::vector<double> radiosity(vtkPolyData* out) {
  vtkDataArray* b = out->GetPointData()->GetArray("Radiosity");
  REQUIRE(b != nullptr);
  std::vector<double> v;
  for (vtkIdType i = 0; i < b->GetNumberOfTuples(); ++i)
    for (int c = 0; c < 3; ++c) v.push_back(b->GetComponent(i, c));
  return v;
}

/// vtkLucentFilter on the scan's own closed isosurface, homogeneous `material`.
std::vector<double> homogeneous(vtkImageData* image, double iso, const char* material) {
  const auto grid =
      lucent::vtkadapter::voxelGridOf(image, image->GetPointData()->GetScalars(), "test scan");
  vtkNew<vtkLucentFilter> filter;
  filter->SetInputData(lucent::vtkadapter::closedIsosurface(grid, iso, "test scan", ""));
  filter->SetMaterial(material);
  filter->SetTechnique("taulut");
  filter->SetKnob("taulut.voxels", "16");
  filter->SetLightDirection(1, 0.4, 0.2);
  filter->Update();
  return radiosity(filter->GetOutput());
}

vtkSmartPointer<vtkLucentVolumeFilter> volumeFilter(vtkImageData* image) {
  auto filter = vtkSmartPointer<vtkLucentVolumeFilter>::New();
  filter->SetInputData(image);
  filter->SetTechnique("taulut");
  filter->SetKnob("taulut.voxels", "16");
  filter->SetLightDirection(1, 0.4, 0.2);
  return filter;
}

std::string coefficients(const lucent::optics::Material& m) {
  auto rgb = [](const auto& v) {
    return std::to_string(v[0]) + "," + std::to_string(v[1]) + "," + std::to_string(v[2]);
  };
  return rgb(m.sigmaA) + "/" + rgb(m.sigmaSPrime);
}

void requireSame(const std::vector<double>& a, const std::vector<double>& b, double tolerance) {
  REQUIRE(a.size() == b.size());
  REQUIRE(!a.empty());
  double diff2 = 0, ref2 = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    REQUIRE(std::isfinite(a[i]));
    diff2 += (a[i] - b[i]) * (a[i] - b[i]), ref2 += b[i] * b[i];
  }
  CHECK(ref2 > 0);
  CHECK(std::sqrt(diff2 / ref2) < tolerance);
}
}  // namespace

TEST_CASE(
    "vtkLucentVolumeFilter: a constant transfer function shades as the material does, the "
    "normalised density as its linear ramp") {
  const auto image = sphereScan();
  const auto marble = *lucent::optics::findMaterial("marble");
  const std::vector<double> expected = homogeneous(image, 0.0, "marble");

  const auto viaTransfer = volumeFilter(image);
  viaTransfer->SetMaterial("marble");  // its eta; the coefficients come from the transfer function
  viaTransfer->SetTransfer(("points:0/" + coefficients(marble)).c_str());
  viaTransfer->SetIsoValue(0.0);
  viaTransfer->Update();
  // std::to_string keeps 6 decimals of the coefficients.
  requireSame(radiosity(viaTransfer->GetOutput()), expected, 1e-6);

  // No transfer function: the value normalised over its range scales the material. On a scan of
  // 0 outside and 1 inside that density is the value itself, so it must shade as the transfer
  // function rising linearly from nothing at 0 to marble at 1 (a coefficient field, which taulut
  // splits into at most 254 media by extinction: within that binning).
  const auto binary = scan(16, [](const glm::dvec3& x) { return glm::length(x) < 12 ? 1.0 : 0.0; });
  const auto viaDensity = volumeFilter(binary), viaRamp = volumeFilter(binary);
  for (vtkLucentVolumeFilter* f : {viaDensity.Get(), viaRamp.Get()}) {
    f->SetMaterial("marble");
    f->SetIsoValue(0.5);
  }
  viaRamp->SetTransfer(("points:0/0/0;1/" + coefficients(marble)).c_str());
  viaDensity->Update();
  viaRamp->Update();
  INFO("the normalised density against the linear ramp");
  requireSame(radiosity(viaDensity->GetOutput()), radiosity(viaRamp->GetOutput()), 0.01);
}

TEST_CASE("vtkLucentVolumeFilter: a label map, with a cavity label, shades its labelled material") {
  // Label 2 = marble shell, 1 = a cavity inside it (none), 0 = outside (none).
  const auto labels = scan(20, [](const glm::dvec3& x) {
    const double r = glm::length(x);
    return r < 6 ? 1.0 : r < 14 ? 2.0 : 0.0;
  });
  const auto filter = volumeFilter(labels);
  filter->SetTransfer("labels:0=none,1=none,2=marble");
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  const auto b = radiosity(out);
  double lit = 0;
  for (double v : b) {
    REQUIRE(std::isfinite(v));
    REQUIRE(v >= 0);
    lit = std::max(lit, v);
  }
  CHECK(lit > 0);
  // The cavity's wall is part of the surface: points within 8 mm of the centre exist.
  bool inner = false;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
    double p[3];
    out->GetPoint(i, p);
    inner |= std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) < 8;
  }
  CHECK(inner);
}

TEST_CASE("vtkLucentVolumeFilter: bad input is an error naming the problem, an empty output") {
  const auto image = sphereScan();
  std::vector<std::string> errors;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetClientData(&errors);
  onError->SetCallback([](vtkObject*, unsigned long, void* sink, void* message) {
    static_cast<std::vector<std::string>*>(sink)->push_back(static_cast<const char*>(message));
  });
  const std::pair<std::string, std::string> cases[] = {
      {"", "selects no voxel"},                                       // IsoValue 100
      {"points:0/-1,0,0/1,1,1", "gives a coefficient outside"},       //
      {"labels:0=none", "with no material"},                          // labels 1..12 present
      {"labels:0=none,1=marble,2=unobtainium", "is not a material"},  //
      {"bogus", "give labels:V=MATERIAL,... or points:V/SA/SS;..."}};
  for (const auto& [transfer, expected] : cases) {
    const auto filter = volumeFilter(image);
    filter->SetMaterial("marble");
    filter->SetTransfer(transfer.c_str());
    filter->SetIsoValue(transfer.empty() ? 100.0 : 0.0);
    filter->AddObserver(vtkCommand::ErrorEvent, onError);
    errors.clear();
    filter->Update();
    INFO(transfer);
    CHECK(filter->GetOutput()->GetNumberOfPoints() == 0);
    REQUIRE(!errors.empty());
    CHECK(errors.front().find(expected) != std::string::npos);
  }
  // A scan without point data: the error says what it has.
  vtkNew<vtkImageData> bare;
  bare->SetDimensions(4, 4, 4);
  const auto filter = volumeFilter(bare);
  filter->AddObserver(vtkCommand::ErrorEvent, onError);
  errors.clear();
  filter->Update();
  CHECK(filter->GetOutput()->GetNumberOfPoints() == 0);
  REQUIRE(!errors.empty());
  CHECK(errors.front().find("it has: none") != std::string::npos);
}
