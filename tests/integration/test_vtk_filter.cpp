// vtkLucentFilter (vtk_plugin/Filters) as a VTK user runs it: on a source, in a pipeline, headless.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>
#include <vtkStringArray.h>
#include <vtkTessellatedBoxSource.h>
#include <vtkTriangleFilter.h>

#include <lucent/technique/registry.hpp>

#include "../unit/chandrasekhar_h.hpp"
#include "lucentPolyDataMesh.h"
#include "vtkLucentFilter.h"

namespace {
// Jensen et al. 2001, Eq. 6 totalled over the plane (their total diffuse reflectance), typed in
// from the paper: Rd = (alpha'/2) (1 + exp(-(4/3) A sqrt(3 (1 - alpha')))) exp(-sqrt(3 (1 -
// alpha'))).
double totalDiffuseReflectance(double sigmaA, double sigmaSPrime, double eta) {
  const double alpha = sigmaSPrime / (sigmaA + sigmaSPrime);
  const double fdr = -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta,
               a = (1 + fdr) / (1 - fdr);
  const double s = std::sqrt(3 * (1 - alpha));
  return 0.5 * alpha * (1 + std::exp(-4.0 / 3.0 * a * s)) * std::exp(-s);
}

// d'Eon 2012's better dipole totalled over the plane, typed in from the note: D Grosjean's,
// A = (1 + 3 C2) / (1 - 2 C1), R = C_phi phi + C_E E integrated, C_k the internal Fresnel moments
// (midpoint rule on a Fresnel formula typed here).
double betterDipoleTotal(double sigmaA, double sigmaSPrime, double eta) {
  const auto fresnelInside = [eta](double cosI) {
    const double sinT = eta * std::sqrt(std::max(0.0, 1 - cosI * cosI));
    if (sinT >= 1) return 1.0;
    const double cosT = std::sqrt(1 - sinT * sinT);
    const double rs = (eta * cosI - cosT) / (eta * cosI + cosT),
                 rp = (cosI - eta * cosT) / (cosI + eta * cosT);
    return (rs * rs + rp * rp) / 2;
  };
  double c1 = 0, c2 = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double mu = (i + 0.5) / n;
    c1 += fresnelInside(mu) * mu / n, c2 += fresnelInside(mu) * mu * mu / n;
  }
  const double st = sigmaA + sigmaSPrime, alpha = sigmaSPrime / st;
  const double d = (2 * sigmaA + sigmaSPrime) / (3 * st * st), str = std::sqrt(sigmaA / d);
  const double zr = 1 / st, zv = zr + 4 * d * (1 + 3 * c2) / (1 - 2 * c1);
  const double flux = (1 - 3 * c2) / 2 * (std::exp(-str * zr) + std::exp(-str * zv));
  const double fluence = (1 - 2 * c1) / (4 * d) * (std::exp(-str * zr) - std::exp(-str * zv)) / str;
  return alpha / 2 * (flux + fluence);
}

// skin1 (Jensen et al. 2001, Fig. 5), typed here.
constexpr double kSkinSigmaA[3] = {0.032, 0.17, 0.48}, kSkinSigmaSPrime[3] = {0.74, 0.88, 1.01},
                 kSkinEta = 1.3;

/// A 60 x 60 x 30 mm box of skin1, lit from +z with irradiance 2, through the reference: far from
/// the edges, the top face is a half-space, where B = Ft(0) E R_total (R integrated over the
/// plane).
void setUpLitSkinSlab(vtkTessellatedBoxSource* box, vtkLucentFilter* filter) {
  box->SetBounds(-30, 30, -30, 30, -15, 15);
  box->SetLevel(24);
  box->QuadsOn();
  filter->SetInputConnection(box->GetOutputPort());
  filter->SetMaterial("skin1");
  filter->SetLightDirection(0, 0, 1);
  filter->SetLightIrradiance(2.0);
  filter->SetKnob("reference.fraction", "1");
}

/// Checks Radiosity at the slab's top face far from its edges (within 6 mm of the axis) against
/// expected(channel) to the relative tolerance; returns how many points were checked.
int checkSlabFaceCentre(vtkPolyData* out, const std::function<double(int)>& expected,
                        double tolerance) {
  vtkDataArray* b = out->GetPointData()->GetArray("Radiosity");
  REQUIRE(b != nullptr);
  int centre = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
    double p[3];
    out->GetPoint(i, p);
    if (std::abs(p[2] - 15) > 1e-9 || std::hypot(p[0], p[1]) >= 6) continue;
    ++centre;
    for (int c = 0; c < 3; ++c) {
      INFO("channel " << c << " at " << p[0] << ", " << p[1]);
      CHECK(b->GetComponent(i, c) == doctest::Approx(expected(c)).epsilon(tolerance));
    }
  }
  return centre;
}
}  // namespace

TEST_CASE(
    "vtkLucentFilter: the profile property picks the better dipole, whose slab face matches its "
    "total") {
  vtkNew<vtkTessellatedBoxSource> box;
  vtkNew<vtkLucentFilter> filter;
  setUpLitSkinSlab(box, filter);
  filter->SetKnob("reference.profile", "better-dipole");
  filter->Update();
  const double ft0 = 1 - std::pow((kSkinEta - 1) / (kSkinEta + 1), 2);
  const int centre = checkSlabFaceCentre(
      filter->GetOutput(),
      [ft0](int c) {
        return 2 * ft0 * betterDipoleTotal(kSkinSigmaA[c], kSkinSigmaSPrime[c], kSkinEta);
      },
      0.03);
  CHECK(centre >= 4);
}

TEST_CASE(
    "vtkLucentFilter: a lit slab's face matches the dipole's total diffuse reflectance, shadowed "
    "side dark, progress") {
  vtkNew<vtkTessellatedBoxSource> box;
  vtkNew<vtkLucentFilter> filter;
  setUpLitSkinSlab(box, filter);
  int progressEvents = 0;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progressEvents);
  onProgress->SetCallback(
      [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
  filter->AddObserver(vtkCommand::ProgressEvent, onProgress);
  filter->Update();

  vtkPolyData* out = filter->GetOutput();
  vtkDataArray* b = out->GetPointData()->GetArray("Radiosity");
  REQUIRE(b != nullptr);
  REQUIRE(out->GetPointData()->GetScalars() != nullptr);
  CHECK(std::string(out->GetPointData()->GetScalars()->GetName()) == "TranslucentColor");
  CHECK(progressEvents >= 10);
  CHECK(filter->GetSampleCount() > 1000);

  const double ft0 = 1 - std::pow((kSkinEta - 1) / (kSkinEta + 1), 2);
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
        CHECK(b->GetComponent(i, c) ==
              doctest::Approx(
                  2 * ft0 * totalDiffuseReflectance(kSkinSigmaA[c], kSkinSigmaSPrime[c], kSkinEta))
                  .epsilon(0.03));
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
  // The shadowed face, 30 mm of skin away from any lit point, is dark: red (diffusion length 3.7
  // mm) passes about e^-8 of the light, blue nothing.
  for (int c = 0; c < 3; ++c) CHECK(bottomMax[c] < 1e-3 * topMean[c] / centre);
}

TEST_CASE(
    "vtkLucentFilter: tiny, huge and eta-extreme inputs stay finite, bad input is an error, not a "
    "crash") {
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(12);
  // A 1 um spectralon sphere is 0.01 transport mean free paths across: outside the diffusion
  // reference's range, so it is refused (empty output), and taulut, valid there, shades it.
  {
    vtkNew<vtkLucentFilter> refused;
    refused->SetInputConnection(sphere->GetOutputPort());
    refused->SetSizeMm(0.001);
    refused->SetMaterial("spectralon");
    refused->GlobalWarningDisplayOff();
    refused->Update();
    CHECK(refused->GetOutput()->GetNumberOfPoints() == 0);
  }
  for (double size : {0.001, 1000.0}) {
    vtkNew<vtkLucentFilter> filter;
    filter->SetInputConnection(sphere->GetOutputPort());
    filter->SetSizeMm(size);
    filter->SetMaterial(size < 1 ? "spectralon" : "ketchup");
    filter->SetTechnique(size < 1 ? "taulut" : "reference");
    filter->SetKnob("reference.max-samples", "20000");
    filter->SetKnob("taulut.voxels", "12");
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

TEST_CASE(
    "vtkLucentFilter: the TSIS technique matches the reference per vertex and converges in N") {
  // A 20 mm skin sphere lit from the side: TSIS (atlas irradiance, mip-ICDF samples, Eq. 10)
  // against the dense dipole sum, vertex by vertex (relative RMS over the vertices, as docs/
  // reports errors).
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(10);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  auto run = [&](const char* technique, int samples) {
    vtkNew<vtkLucentFilter> filter;
    filter->SetInputConnection(sphere->GetOutputPort());
    filter->SetMaterial("skin1");
    filter->SetLightDirection(1, 0.3, 0.4);
    filter->SetTechnique(technique);
    filter->SetKnobInteger("tsis.samples", samples);
    filter->SetKnobInteger("tsis.atlas-resolution", 512);
    filter->Update();
    vtkDataArray* b = filter->GetOutput()->GetPointData()->GetArray("Radiosity");
    REQUIRE(b != nullptr);
    std::vector<double> values(std::size_t(3 * b->GetNumberOfTuples()));
    for (vtkIdType i = 0; i < b->GetNumberOfTuples(); ++i)
      for (int c = 0; c < 3; ++c) values[std::size_t(3 * i + c)] = b->GetComponent(i, c);
    return values;
  };
  const auto reference = run("reference", 0);
  double error[2][3];
  const int counts[2] = {1024, 8192};
  for (int k = 0; k < 2; ++k) {
    const auto tsis = run("tsis", counts[k]);
    REQUIRE(tsis.size() == reference.size());
    for (int c = 0; c < 3; ++c) {
      double d2 = 0, r2 = 0;
      for (std::size_t i = std::size_t(c); i < tsis.size(); i += 3) {
        REQUIRE(std::isfinite(tsis[i]));
        d2 += (tsis[i] - reference[i]) * (tsis[i] - reference[i]);
        r2 += reference[i] * reference[i];
      }
      error[k][c] = std::sqrt(d2 / r2);
      MESSAGE("TSIS N = " << counts[k] << ", channel " << c
                          << ": relative RMS against the reference " << error[k][c]);
    }
  }
  for (int c = 0; c < 3; ++c) CHECK(error[1][c] < 0.05);
  CHECK(error[1][2] < error[0][2] / 1.4);
}

namespace {
/// Radiance = level at every vertex: what the filter passes through can be checked exactly.
lucent::technique::Technique vertexConstant() {
  namespace lt = lucent::technique;
  lt::Technique t;
  t.name = "test-vertex-constant";
  t.summary = "test only";
  t.paper = "none";
  t.knobs = {lt::KnobSpec::real("level", "0.5", 0, 1, "", "the radiance returned")};
  t.defaultSweep = {{"level", {"0.5"}}};
  struct Constant final : lt::Prepared {
    double level;
    explicit Constant(double v) : level(v) {}
    lt::FrameResult frame(const lt::SceneDescription&, const lt::ShadeRequest& r,
                          lt::Statistics&) override {
      lt::FrameResult out;
      out.radiance.assign(r.points.size(), glm::dvec3(level));
      return out;
    }
  };
  t.prepare = [](const lt::SceneDescription&, const lt::KnobValues& k, lt::Statistics&) {
    return std::make_unique<Constant>(k.real("level"));
  };
  return t;
}
}  // namespace

TEST_CASE(
    "vtkLucentFilter: a technique registered by a test alone is offered, with its knob as a "
    "property") {
  auto& registry = vtkLucentFilter::Techniques();
  if (!registry.find("test-vertex-constant")) registry.add(vertexConstant());
  std::vector<std::string> techniques, properties;
  for (int i = 0; i < vtkLucentFilter::GetNumberOfTechniques(); ++i)
    techniques.push_back(vtkLucentFilter::GetTechniqueName(i));
  for (int i = 0; i < vtkLucentFilter::GetNumberOfKnobProperties(); ++i)
    properties.push_back(vtkLucentFilter::GetKnobPropertyName(i));
  auto has = [](const std::vector<std::string>& v, const std::string& x) {
    return std::find(v.begin(), v.end(), x) != v.end();
  };
  CHECK(has(techniques, "test-vertex-constant"));
  CHECK(has(techniques, "tsis"));
  CHECK_FALSE(has(techniques, "pathtrace"));  // it needs a camera: not a per-vertex technique
  CHECK(has(properties, "TestVertexConstantLevel"));
  CHECK(has(properties, "TsisSamples"));
  CHECK(has(properties, "HybridRingSamples"));

  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkLucentFilter> filter;
  filter->SetInputConnection(sphere->GetOutputPort());
  filter->SetTechnique("test-vertex-constant");
  CHECK(filter->GetKnob("test-vertex-constant.level") == "0.5");
  filter->SetKnobReal("test-vertex-constant.level", 0.25);
  filter->Update();
  vtkDataArray* radiance = filter->GetOutput()->GetPointData()->GetArray("Radiance");
  REQUIRE(radiance != nullptr);
  REQUIRE(radiance->GetNumberOfTuples() > 10);
  for (vtkIdType i = 0; i < radiance->GetNumberOfTuples(); ++i)
    CHECK(radiance->GetComponent(i, 1) == doctest::Approx(0.25));
  CHECK(filter->GetOutput()->GetPointData()->GetArray("Radiosity") == nullptr);  // it computes no B

  // A value outside the knob's own range is an error before any work, and the output stays empty.
  filter->SetKnob("test-vertex-constant.level", "3");
  filter->GlobalWarningDisplayOff();
  filter->Update();
  CHECK(filter->GetOutput()->GetNumberOfPoints() == 0);
}

TEST_CASE(
    "vtkLucentFilter: the voxel optical-thickness LUT per vertex — a lit face gives back the "
    "light it takes in (Eq. 1-3's kernel normalised), the far face what passes through") {
  // A 40 x 40 x 10 mm box of skin, lit from +z with irradiance 2: on the top face, far from the
  // edges, B = Ft(0) E (the kernel (sigma_t^2 / 2 pi) e^{-sigma_t r} integrates to 1); on the
  // bottom face B = Ft(0) E (1 + sigma_t d) e^{-sigma_t d} through d = 10 mm
  // (tau_lut_radiance.hpp).
  vtkNew<vtkTessellatedBoxSource> box;
  box->SetBounds(-20, 20, -20, 20, -5, 5);
  box->SetLevel(40);
  box->QuadsOn();
  vtkNew<vtkLucentFilter> filter;
  filter->SetInputConnection(box->GetOutputPort());
  filter->SetMaterial("skin1");
  filter->SetTechnique("taulut");
  filter->SetKnob("taulut.voxels", "40");
  filter->SetKnob("taulut.rings", "40");
  filter->SetKnob("taulut.map", "1024");
  filter->SetLightDirection(0, 0, 1);
  filter->SetLightIrradiance(2.0);
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  vtkDataArray* b = out->GetPointData()->GetArray("Radiosity");
  REQUIRE(b != nullptr);
  const double eta = 1.3, ft0 = 1 - std::pow((eta - 1) / (eta + 1), 2);
  const double sigmaT[3] = {0.032 + 0.74, 0.17 + 0.88, 0.48 + 1.01};
  int top = 0, bottom = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
    double p[3];
    out->GetPoint(i, p);
    if (std::hypot(p[0], p[1]) > 8) continue;
    const bool isTop = std::abs(p[2] - 5) < 1e-9, isBottom = std::abs(p[2] + 5) < 1e-9;
    top += isTop, bottom += isBottom;
    for (int c = 0; c < 3; ++c) {
      INFO("channel " << c << " at " << p[0] << ", " << p[1] << ", " << p[2]);
      if (isTop) CHECK(b->GetComponent(i, c) == doctest::Approx(2 * ft0).epsilon(0.04));
      const double through = 2 * ft0 * (1 + sigmaT[c] * 10) * std::exp(-sigmaT[c] * 10);
      if (isBottom) CHECK(b->GetComponent(i, c) == doctest::Approx(through).epsilon(0.1));
    }
  }
  CHECK(top > 20);
  CHECK(bottom > 20);
}

TEST_CASE(
    "vtkLucentFilter: a block marked as an inner body fills the surface around it (taulut), bad "
    "bodies are errors") {
  // A marble sphere 2.3 mm across (SizeMm 4: the box diagonal) holding a sphere of 3/4 its radius,
  // lit from the side: the shell is under a mean free path thick, so paths cross the inner body.
  auto sphereOf = [](double radius) {
    vtkNew<vtkSphereSource> s;
    s->SetRadius(radius);
    s->SetThetaResolution(32);
    s->SetPhiResolution(16);
    s->Update();
    auto out = vtkSmartPointer<vtkPolyData>::New();
    out->DeepCopy(s->GetOutput());
    return out;
  };
  auto run = [&](const char* innerMaterial, double innerRadius) {
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetBlock(0, sphereOf(4.0));
    if (innerMaterial) {
      auto inner = sphereOf(innerRadius);
      lucent::vtkadapter::markInnerBody(inner, innerMaterial);
      blocks->SetBlock(1, inner);
    }
    vtkNew<vtkLucentFilter> filter;
    filter->SetInputData(blocks);
    filter->SetMaterial("marble");
    filter->SetSizeMm(4);
    filter->SetTechnique("taulut");
    filter->SetKnob("taulut.voxels", "24");
    filter->SetKnob("taulut.precision", "fp32");  // fp16 would round each medium's length apart
    filter->SetLightDirection(1, 0.2, 0.1);
    filter->GlobalWarningDisplayOff();
    filter->Update();
    std::vector<double> b;
    if (vtkDataArray* a = filter->GetOutput()->GetPointData()->GetArray("Radiosity"))
      for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
        for (int c = 0; c < 3; ++c) b.push_back(a->GetComponent(i, c));
    return b;
  };
  const auto plain = run(nullptr, 0), sameMaterial = run("marble", 3.0),
             ketchup = run("ketchup", 3.0);
  REQUIRE(!plain.empty());
  REQUIRE(sameMaterial.size() == plain.size());
  REQUIRE(ketchup.size() == plain.size());  // the inner body is not part of the output surface
  double d2 = 0, r2 = 0, sumKetchup = 0, sumPlain = 0;
  for (std::size_t i = 0; i < plain.size(); ++i) {
    d2 += (sameMaterial[i] - plain[i]) * (sameMaterial[i] - plain[i]), r2 += plain[i] * plain[i];
    sumKetchup += ketchup[i], sumPlain += plain[i];
  }
  // Marble inside marble is marble (tau summed over two media of one sigma_t).
  CHECK(std::sqrt(d2 / r2) < 1e-5);
  // taulut sees extinction only, and ketchup's is below marble's in every channel.
  MESSAGE("summed radiosity: ketchup inside " << sumKetchup << ", all marble " << sumPlain);
  CHECK(sumKetchup > 1.01 * sumPlain);
  CHECK(run("unobtainium", 3.0).empty());  // not a material: refused
  CHECK(run("ketchup", 6.0).empty());      // not inside the object: refused
}

namespace {
/// The text of the last error a VTK object reported (its ErrorEvent's call data).
struct ErrorCapture {
  std::string last;
  vtkNew<vtkCallbackCommand> command;
  explicit ErrorCapture(vtkObject* object) {
    command->SetClientData(this);
    command->SetCallback([](vtkObject*, unsigned long, void* self, void* text) {
      static_cast<ErrorCapture*>(self)->last = text ? static_cast<const char*>(text) : "";
    });
    object->AddObserver(vtkCommand::ErrorEvent, command);
  }
};

std::vector<std::string> stringValues(vtkAbstractArray* array) {
  std::vector<std::string> out;
  if (auto* strings = vtkStringArray::SafeDownCast(array))
    for (vtkIdType i = 0; i < strings->GetNumberOfValues(); ++i)
      out.push_back(strings->GetValue(i));
  return out;
}
}  // namespace

TEST_CASE(
    "vtkLucentFilter: Technique auto shades with the planner's choice, an offered technique, and "
    "puts the plan's reasons in the output's field data, and the lit slab face still matches the "
    "dipole's total") {
  vtkNew<vtkTessellatedBoxSource> box;
  vtkNew<vtkLucentFilter> filter;
  setUpLitSkinSlab(box, filter);
  filter->SetTechnique("auto");
  filter->SetBudgetMs(500);
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  const auto chosen = stringValues(out->GetFieldData()->GetAbstractArray("LucentTechnique"));
  const auto plan = stringValues(out->GetFieldData()->GetAbstractArray("LucentPlan"));
  REQUIRE(chosen.size() == 1);
  CHECK(chosen[0] == filter->GetChosenTechnique());
  const std::string name = chosen[0].substr(0, chosen[0].find(':'));
  bool offered = false;
  for (int i = 0; i < vtkLucentFilter::GetNumberOfTechniques(); ++i)
    offered = offered || vtkLucentFilter::GetTechniqueName(i) == name;
  CHECK_MESSAGE(offered, "auto chose " << chosen[0]);
  REQUIRE(plan.size() >= 3);
  CHECK(plan[0].rfind("scene:", 0) == 0);
  bool namesChoice = false;
  for (const auto& line : plan) namesChoice = namesChoice || line.find(name) != std::string::npos;
  CHECK(namesChoice);

  // Whatever it chose, the lit face far from the edges is the half-space's B = Ft(0) E R_total
  // within the dipole techniques' accuracy (the planner's default target is 5 %; 10 % here).
  const double ft0 = 1 - std::pow((kSkinEta - 1) / (kSkinEta + 1), 2);
  const int centre = checkSlabFaceCentre(
      out,
      [ft0](int c) {
        return 2 * ft0 * totalDiffuseReflectance(kSkinSigmaA[c], kSkinSigmaSPrime[c], kSkinEta);
      },
      0.1);
  CHECK(centre >= 4);
}

TEST_CASE(
    "vtkLucentFilter: Technique auto without its calibration is an error naming the file and the "
    "fix, before any work") {
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkLucentFilter> filter;
  filter->SetInputConnection(sphere->GetOutputPort());
  filter->SetSizeMm(20);
  filter->SetTechnique("auto");
  filter->SetCalibrationDirectory("/nonexistent/lucent-calibration");
  ErrorCapture errors(filter);  // VTK reports to an observer instead of the output window
  filter->Update();
  CHECK(filter->GetOutput()->GetNumberOfPoints() == 0);
  INFO(errors.last);
  CHECK(errors.last.find("/nonexistent/lucent-calibration/settings.csv") != std::string::npos);
  CHECK(errors.last.find("calibrate_planner.py") != std::string::npos);
  CHECK(errors.last.find("CalibrationDirectory") != std::string::npos);
}

TEST_CASE(
    "vtkLucentFilter: the random walk per vertex, index-matched, gives a thick slab's lit face "
    "Chandrasekhar's half-space radiance") {
  // Index-matched and isotropic (g 0: sigma_s = sigma_s'), the walk is exact, and a slab of about
  // 30 mean free paths is a half-space at its face's centre: (a E / 4pi) H(1)^2 / 2 towards the
  // normal.
  vtkNew<vtkTessellatedBoxSource> box;
  box->SetBounds(-30, 30, -30, 30, -15, 15);
  box->SetLevel(4);
  box->QuadsOn();
  vtkNew<vtkLucentFilter> filter;
  filter->SetInputConnection(box->GetOutputPort());
  filter->SetMaterial("skin1");
  filter->SetLightDirection(0, 0, 1);
  filter->SetLightIrradiance(2.0);
  filter->SetTechnique("randomwalk");
  filter->SetKnob("randomwalk.boundary", "matched");
  filter->SetKnob("randomwalk.spp", "4096");  // 4 points: about 1 % standard error
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  vtkDataArray* radiance = out->GetPointData()->GetArray("Radiance");
  REQUIRE(radiance != nullptr);
  double mean[3] = {0, 0, 0};
  int centre = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
    double p[3];
    out->GetPoint(i, p);
    for (int c = 0; c < 3; ++c) CHECK(std::isfinite(radiance->GetComponent(i, c)));
    if (std::abs(p[2] - 15) > 1e-9 || std::hypot(p[0], p[1]) > 16) continue;
    ++centre;
    for (int c = 0; c < 3; ++c) mean[c] += radiance->GetComponent(i, c);
  }
  REQUIRE(centre >= 4);
  for (int c = 0; c < 3; ++c) {
    const double albedo = kSkinSigmaSPrime[c] / (kSkinSigmaSPrime[c] + kSkinSigmaA[c]);
    const double exact = 2.0 * lucent::test::halfSpaceReflected(1.0, albedo);
    INFO("channel " << c << ": " << mean[c] / centre << ", exact " << exact);
    CHECK(mean[c] / centre == doctest::Approx(exact).epsilon(0.04));
  }
}
