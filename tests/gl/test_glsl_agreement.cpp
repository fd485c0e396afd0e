// One source of truth: the GLSL twins in shaders/ (with constants generated from optics/constants.hpp)
// evaluated on the GPU must agree with the C++ of include/lucent/. Each pixel returns its own input in
// alpha, so the C++ evaluates at exactly the float the GPU used.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <lucent/image/display_encode.hpp>
#include <lucent/optics/dipole.hpp>
#include <lucent/optics/fresnel.hpp>
#include <lucent/optics/materials.hpp>

#include "gl_context.hpp"
#include "lucent_glsl.h"

namespace {
constexpr int kWidth = 256;

std::string probeShader(const std::string& body) {
  std::string fs =
      "//VTK::System::Dec\n//VTK::Output::Dec\n" + std::string(lucent::glsl::kConstants) + lucent::glsl::kOpticsGlsl +
      lucent::glsl::kDisplayGlsl +
      "in vec2 texCoord;\nuniform LucentDipole dipole;\nuniform float eta;\n"
      "void main() {\n  float t = floor(texCoord.x * 256.0) / 255.0;\n" + body + "}\n";
  return fs;
}
}  // namespace

TEST_CASE("GLSL Rd(r) agrees with optics/dipole.hpp for every measured material, r from 1 um to 1 m") {
  lucent_test::QuadProbe probe(kWidth, 1);
  REQUIRE(probe.program(probeShader(
      "  float r = 1e-3 * pow(1e6, t);\n  gl_FragData[0] = vec4(lucentDipoleRd(dipole, r), r);\n")));
  int compared = 0;
  for (const auto& entry : lucent::optics::kMeasuredMaterials) {
    const auto m = *lucent::optics::findMaterial(std::string(entry.name));
    const auto d = lucent::optics::Dipole<double>::make(m.sigmaA, m.sigmaSPrime, m.eta);
    float v[4][3];
    for (int c = 0; c < 3; ++c) {
      v[0][c] = float(d.channel[c].sigmaTr), v[1][c] = float(d.channel[c].zr);
      v[2][c] = float(d.channel[c].zv), v[3][c] = float(d.channel[c].alphaPrime);
    }
    probe.shader()->SetUniform3f("dipole.sigmaTr", v[0]);
    probe.shader()->SetUniform3f("dipole.zr", v[1]);
    probe.shader()->SetUniform3f("dipole.zv", v[2]);
    probe.shader()->SetUniform3f("dipole.alphaPrime", v[3]);
    const std::vector<float> out = probe.draw();
    // The C++ with the same float parameters (the derivation is the C++'s; the GPU gets its result).
    lucent::optics::Dipole<double> f = d;
    for (int c = 0; c < 3; ++c) {
      f.channel[c].sigmaTr = v[0][c], f.channel[c].zr = v[1][c], f.channel[c].zv = v[2][c];
      f.channel[c].alphaPrime = v[3][c];
    }
    double peak = 0;
    for (int i = 0; i < kWidth; ++i) peak = std::max(peak, f.rd(double(out[4 * i + 3]))[0]);
    for (int i = 0; i < kWidth; ++i) {
      const double r = out[4 * i + 3];
      const auto expected = f.rd(r);
      for (int c = 0; c < 3; ++c) {
        const double gpu = out[4 * i + c];
        INFO(std::string(entry.name) << " r=" << r << " mm channel " << c << ": GPU " << gpu << ", C++ " << expected[c]);
        REQUIRE(std::isfinite(gpu));
        // float against double: relative 2e-5 (exp of an argument with float rounding), or float's
        // underflow far below the profile's peak.
        CHECK(std::abs(gpu - expected[c]) <= 2e-5 * std::abs(expected[c]) + 1e-30 + 1e-7 * peak);
        ++compared;
      }
    }
  }
  CHECK(compared == 3 * kWidth * int(lucent::optics::kMeasuredMaterials.size()));
}

TEST_CASE("GLSL Fresnel and Fdr agree with optics/fresnel.hpp, eta 1 to 3, normal to grazing incidence") {
  lucent_test::QuadProbe probe(kWidth, 1);
  REQUIRE(probe.program(probeShader(
      "  gl_FragData[0] = vec4(lucentFresnelTransmittance(t, eta), lucentFresnelReflectance(t, eta),\n"
      "                        lucentDiffuseFresnelReflectance(1.0 + 2.0 * t), t);\n")));
  for (const float eta : {1.0f, 1.3f, 1.5f, 2.4f, 3.0f}) {
    probe.shader()->SetUniformf("eta", eta);
    const std::vector<float> out = probe.draw();
    for (int i = 0; i < kWidth; ++i) {
      const double c = out[4 * i + 3];
      INFO("eta " << eta << " cos " << c);
      CHECK(out[4 * i + 0] == doctest::Approx(lucent::optics::fresnelTransmittance(c, double(eta))).epsilon(1e-5));
      CHECK(std::abs(out[4 * i + 1] - lucent::optics::fresnelReflectance(c, double(eta))) <= 2e-6);
      const double etaFdr = double(1.0f + 2.0f * float(c));
      CHECK(std::abs(out[4 * i + 2] - lucent::optics::diffuseFresnelReflectance(etaFdr)) <= 2e-6);
    }
  }
}

TEST_CASE("GLSL display curve agrees with image/display_encode.hpp from 1e-3 to 1e3") {
  lucent_test::QuadProbe probe(kWidth, 1);
  REQUIRE(probe.program(probeShader(
      "  float x = 1e-3 * pow(1e6, t);\n  gl_FragData[0] = vec4(lucentDisplayEncode(vec3(x, 0.0, -x)), x);\n")));
  const std::vector<float> out = probe.draw();
  for (int i = 0; i < kWidth; ++i) {
    const double x = out[4 * i + 3];
    INFO("x " << x);
    CHECK(std::abs(out[4 * i + 0] - lucent::image::displayEncode(x)) <= 2e-6);
    CHECK(out[4 * i + 1] == 0.0f);
    CHECK(out[4 * i + 2] == 0.0f);  // negative radiance shows black, as on the CPU
  }
}
