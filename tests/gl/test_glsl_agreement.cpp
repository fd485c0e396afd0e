// One source of truth: the GLSL twins in shaders/ (with constants generated from
// optics/constants.hpp) evaluated on the GPU must agree with the C++ of include/lucent/. Each pixel
// returns its own input in alpha, so the C++ evaluates at exactly the float the GPU used.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <lucent/image/display_encode.hpp>
#include <lucent/optics/dipole.hpp>
#include <lucent/optics/fresnel.hpp>
#include <lucent/optics/materials.hpp>
#include <lucent/optics/profile.hpp>
#include <lucent/technique/texture_space.hpp>

#include <vtkNew.h>

#include "gl_context.hpp"
#include "lucent_glsl.h"
#include "vtkLucentProfile.h"

namespace {
namespace lo = lucent::optics;
namespace lt = lucent::technique;
constexpr int kWidth = 256;

std::string probeShader(const std::string& body, const std::string& uniforms = "") {
  std::string fs =
      "//VTK::System::Dec\n//VTK::Output::Dec\n" + std::string(lucent::glsl::kConstants) +
      lucent::glsl::kOpticsGlsl + lucent::glsl::kDisplayGlsl +
      "in vec2 texCoord;\nuniform LucentDipole dipole;\nuniform float eta;\n" + uniforms +
      "void main() {\n  float t = floor(texCoord.x * 256.0) / 255.0;\n" + body + "}\n";
  return fs;
}
}  // namespace

TEST_CASE(
    "GLSL Rd(r) of the classic and the better dipole agrees with optics/dipole.hpp for every "
    "measured material, r from 1 um to 1 m") {
  lucent_test::QuadProbe probe(kWidth, 1);
  REQUIRE(
      probe.program(probeShader("  float r = 1e-3 * pow(1e6, t);\n  gl_FragData[0] = "
                                "vec4(lucentDipoleRd(dipole, r), r);\n")));
  const char* names[6] = {"dipole.sigmaTr",    "dipole.zr",         "dipole.zv",
                          "dipole.alphaPrime", "dipole.fluxWeight", "dipole.fluenceWeight"};
  int compared = 0;
  for (const auto model : {lo::ProfileModel::Dipole, lo::ProfileModel::BetterDipole})
    for (const auto& entry : lo::kMeasuredMaterials) {
      const auto m = *lo::findMaterial(std::string(entry.name));
      const auto d = lo::Profile<double>::make(model, m.sigmaA, m.sigmaSPrime, m.eta).poles();
      float v[6][3];
      for (int c = 0; c < 3; ++c) {
        const auto& ch = d.channel[c];
        const double p[6] = {ch.sigmaTr,    ch.zr,         ch.zv,
                             ch.alphaPrime, ch.fluxWeight, ch.fluenceWeight};
        for (int k = 0; k < 6; ++k) v[k][c] = float(p[k]);
      }
      for (int k = 0; k < 6; ++k) probe.shader()->SetUniform3f(names[k], v[k]);
      const std::vector<float> out = probe.draw();
      // The C++ with the same float parameters (the derivation is the C++'s; the GPU gets its
      // result).
      lo::Dipole<double> f = d;
      for (int c = 0; c < 3; ++c) {
        auto& ch = f.channel[c];
        ch.sigmaTr = v[0][c], ch.zr = v[1][c], ch.zv = v[2][c], ch.alphaPrime = v[3][c];
        ch.fluxWeight = v[4][c], ch.fluenceWeight = v[5][c];
      }
      double peak = 0;
      for (int i = 0; i < kWidth; ++i) peak = std::max(peak, f.rd(double(out[4 * i + 3]))[0]);
      for (int i = 0; i < kWidth; ++i) {
        const double r = out[4 * i + 3];
        const auto expected = f.rd(r);
        for (int c = 0; c < 3; ++c) {
          const double gpu = out[4 * i + c];
          INFO(lo::profileModelInfo(model).name << " " << entry.name << " r=" << r << " mm channel "
                                                << c << ": GPU " << gpu << ", C++ " << expected[c]);
          REQUIRE(std::isfinite(gpu));
          // float against double: relative 2e-5 (exp of an argument with float rounding), or
          // float's underflow far below the profile's peak.
          CHECK(std::abs(gpu - expected[c]) <= 2e-5 * std::abs(expected[c]) + 1e-30 + 1e-7 * peak);
          ++compared;
        }
      }
    }
  CHECK(compared == 2 * 3 * kWidth * int(lo::kMeasuredMaterials.size()));
}

TEST_CASE(
    "The pass's profile (vtkLucentProfile) on the GPU: every model's table meets RadialTable's "
    "bound against the double profile, the closed form agrees, exitScale as on the CPU") {
  // What stage 3 of the pass evaluates, with the uniforms vtkLucentProfile sets: r from 0 to 1.2
  // rMax (beyond rMax the table is 0).
  constexpr double kDiagonalMm = 40.0;
  // The pass compiles stage 3 once per form (LUCENT_CLOSED_FORM); the probe does the same.
  auto shaderOfForm = [&](bool closedForm) {
    return probeShader("  float r = t == 0.0 ? 0.0 : 1e-5 * pow(1.2 * " +
                           std::to_string(kDiagonalMm) +
                           " / 1e-5, t);\n"
                           "#if LUCENT_CLOSED_FORM\n"
                           "  vec3 rd = lucentDipoleRd(dipole, r);\n"
                           "#else\n"
                           "  vec3 rd = lucentRadialTableRd(profileTable, profile, r);\n"
                           "#endif\n"
                           "  gl_FragData[0] = vec4(exitScale * rd, r);\n",
                       std::string("#define LUCENT_CLOSED_FORM ") + (closedForm ? "1" : "0") +
                           "\nuniform float exitScale;\nuniform sampler2D profileTable;\n"
                           "uniform LucentRadialTable profile;\n");
  };
  lucent_test::QuadProbe probe(kWidth, 1);
  int compiledForm = -1;
  const auto tsis = lt::tsisTechnique();
  int tables = 0, closed = 0;
  for (const auto& model : lo::kProfileModels)
    for (const char* rd : {"table", "exact"})
      for (const auto& entry : lo::kMeasuredMaterials) {
        const auto m = *lo::findMaterial(std::string(entry.name));
        const auto knobs = tsis.values({{"profile", std::string(model.name)}, {"rd", rd}});
        vtkNew<vtkLucentProfile> gpu;
        std::string warning, error;
        REQUIRE(gpu->Update(probe.window(), m, knobs, kDiagonalMm, warning, error));
        const auto exact = lt::detail::profileOf<double>(m, knobs);
        CHECK(gpu->IsClosedForm() == (std::string(rd) == "exact" && exact.isPolePair()));
        CHECK(warning.empty() == (std::string(rd) == "table" || exact.isPolePair()));
        if (compiledForm != int(gpu->IsClosedForm())) {
          REQUIRE(probe.program(shaderOfForm(gpu->IsClosedForm())));
          compiledForm = int(gpu->IsClosedForm());
        }
        gpu->Activate(probe.shader());
        const std::vector<float> out = probe.draw();
        gpu->Deactivate();
        (gpu->IsClosedForm() ? closed : tables) += 1;
        const lo::RdTableBound<float> bound;
        const auto r0 = exact.regularFrom();  // the table's bound holds from here on, per channel
        glm::dvec3 peak;
        for (int c = 0; c < 3; ++c) peak[c] = exact.rd(r0[c])[c];
        for (int i = 0; i < kWidth; ++i) {
          const double r = out[4 * i + 3];
          const auto want = exact.rd(r) * exact.exitScale;
          for (int c = 0; c < 3; ++c) {
            const double got = out[4 * i + c];
            INFO(model.name << " rd=" << rd << " " << entry.name << " r=" << r << " mm channel "
                            << c << ": GPU " << got << ", C++ " << want[c]);
            REQUIRE(std::isfinite(got));
            if (r > kDiagonalMm) {
              if (!gpu->IsClosedForm()) CHECK(got == 0.0f);
              continue;
            }
            if (r < r0[c]) continue;
            // The table's stated bound (RdTableBound), with float's rounding of the profile on top.
            const double allowed =
                gpu->IsClosedForm()
                    ? 2e-5 * want[c] + 1e-7 * peak[c] * exact.exitScale + 1e-30
                    : 1.05 * double(bound.relTol) *
                              std::max(want[c], double(bound.floor) * peak[c] * exact.exitScale) +
                          2e-6 * want[c];
            CHECK(std::abs(got - want[c]) <= allowed);
          }
        }
      }
  const int materials = int(lo::kMeasuredMaterials.size());
  CHECK(closed == 2 * materials);  // rd=exact for the two dipoles
  CHECK(tables == (2 * int(lo::kProfileModels.size()) - 2) * materials);
}

TEST_CASE(
    "GLSL Fresnel and Fdr agree with optics/fresnel.hpp, eta 1 to 3, normal to grazing incidence") {
  lucent_test::QuadProbe probe(kWidth, 1);
  REQUIRE(probe.program(probeShader(
      "  gl_FragData[0] = vec4(lucentFresnelTransmittance(t, eta), lucentFresnelReflectance(t, "
      "eta),\n"
      "                        lucentDiffuseFresnelReflectance(1.0 + 2.0 * t), t);\n")));
  for (const float eta : {1.0f, 1.3f, 1.5f, 2.4f, 3.0f}) {
    probe.shader()->SetUniformf("eta", eta);
    const std::vector<float> out = probe.draw();
    for (int i = 0; i < kWidth; ++i) {
      const double c = out[4 * i + 3];
      INFO("eta " << eta << " cos " << c);
      CHECK(out[4 * i + 0] ==
            doctest::Approx(lucent::optics::fresnelTransmittance(c, double(eta))).epsilon(1e-5));
      CHECK(std::abs(out[4 * i + 1] - lucent::optics::fresnelReflectance(c, double(eta))) <= 2e-6);
      const double etaFdr = double(1.0f + 2.0f * float(c));
      CHECK(std::abs(out[4 * i + 2] - lucent::optics::diffuseFresnelReflectance(etaFdr)) <= 2e-6);
    }
  }
}

TEST_CASE("GLSL display curve agrees with image/display_encode.hpp from 1e-3 to 1e3") {
  lucent_test::QuadProbe probe(kWidth, 1);
  REQUIRE(
      probe.program(probeShader("  float x = 1e-3 * pow(1e6, t);\n  gl_FragData[0] = "
                                "vec4(lucentDisplayEncode(vec3(x, 0.0, -x)), x);\n")));
  const std::vector<float> out = probe.draw();
  for (int i = 0; i < kWidth; ++i) {
    const double x = out[4 * i + 3];
    INFO("x " << x);
    CHECK(std::abs(out[4 * i + 0] - lucent::image::displayEncode(x)) <= 2e-6);
    CHECK(out[4 * i + 1] == 0.0f);
    CHECK(out[4 * i + 2] == 0.0f);  // negative radiance shows black, as on the CPU
  }
}
