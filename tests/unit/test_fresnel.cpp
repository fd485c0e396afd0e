#include <doctest/doctest.h>

#include <cmath>
#include <lucent/optics/constants.hpp>
#include <lucent/optics/fresnel.hpp>

using namespace lucent::optics;

namespace {
// Independent form of the Fresnel equations, in angles (Hecht, Optics, Eq. 4.42-4.43).
double fresnelByAngles(double thetaI, double eta) {
  const double sinT = std::sin(thetaI) / eta;
  if (sinT >= 1) return 1;
  const double thetaT = std::asin(sinT);
  if (thetaI == 0) {
    const double r = (eta - 1) / (eta + 1);
    return r * r;
  }
  const double rs = -std::sin(thetaI - thetaT) / std::sin(thetaI + thetaT);
  const double rp = std::tan(thetaI - thetaT) / std::tan(thetaI + thetaT);
  return 0.5 * (rs * rs + rp * rp);
}
}  // namespace

TEST_CASE("Fresnel reflectance at normal incidence is ((eta-1)/(eta+1))^2") {
  for (double eta : {1.0, 1.3, 1.5, 2.0, 2.5, 3.0}) {
    const double r = (eta - 1) / (eta + 1);
    CHECK(fresnelReflectance(1.0, eta) == doctest::Approx(r * r).epsilon(1e-12));
  }
}

TEST_CASE("Fresnel reflectance matches the angle form of the Fresnel equations") {
  for (double eta : {1.1, 1.3, 1.5, 2.5, 0.75})
    for (double deg = 1; deg < 90; deg += 2.5) {
      const double t = deg * kPi / 180;
      CHECK(fresnelReflectance(std::cos(t), eta) == doctest::Approx(fresnelByAngles(t, eta)).epsilon(1e-10));
    }
}

TEST_CASE("Fresnel limits: grazing incidence reflects all, eta = 1 transmits all, total internal reflection") {
  CHECK(fresnelReflectance(0.0, 1.3) == 1.0);
  CHECK(fresnelReflectance(0.0, 1.0) == 1.0);  // grazing with eta = 1 is 0/0 in the formulas: defined as 1
  for (double c = 0.01; c <= 1.0; c += 0.01) CHECK(fresnelTransmittance(c, 1.0) == doctest::Approx(1.0).epsilon(1e-12));
  // From glass to air (eta = 1/1.5) beyond the critical angle asin(1/1.5) ~ 41.8 degrees.
  CHECK(fresnelReflectance(std::cos(45.0 * kPi / 180), 1 / 1.5) == 1.0);
  CHECK(fresnelReflectance(std::cos(40.0 * kPi / 180), 1 / 1.5) < 1.0);
  // Out-of-range cosines are clamped, never NaN.
  CHECK(std::isfinite(fresnelReflectance(-0.5, 1.3)));
  CHECK(fresnelReflectance(1.5, 1.3) == fresnelReflectance(1.0, 1.3));
}

TEST_CASE("Diffuse Fresnel reflectance and A stay physical on the supported eta range") {
  for (double eta = kEtaMin; eta <= kEtaMax + 1e-12; eta += 0.05) {
    const double fdr = diffuseFresnelReflectance(eta);
    CHECK(fdr > 0);
    CHECK(fdr < 1);
    CHECK(boundaryMismatch(eta) >= 1);
    CHECK(std::isfinite(boundaryMismatch(eta)));
  }
}

TEST_CASE("The Fdr polynomial fit agrees with the exact internal diffuse reflectance") {
  // Light inside the medium (relative index eta), cosine-weighted over the hemisphere: the exact diffuse
  // reflectance is int_0^1 Fr(mu; 1/eta) 2 mu dmu (integrated here by Simpson, independent of the fit).
  for (double eta : {1.1, 1.3, 1.5, 2.0, 2.5}) {
    const int n = 200000;
    double sum = 0;
    for (int i = 0; i <= n; ++i) {
      const double mu = double(i) / n;
      const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
      sum += w * fresnelReflectance(mu, 1.0 / eta) * 2 * mu;
    }
    const double exact = sum / (3.0 * n);
    INFO("eta = " << eta << ", exact " << exact << ", fit " << diffuseFresnelReflectance(eta));
    CHECK(std::abs(diffuseFresnelReflectance(eta) - exact) < 0.01);
  }
}
