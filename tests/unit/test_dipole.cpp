#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <lucent/optics/dipole.hpp>
#include <lucent/optics/materials.hpp>

#include "quadrature.hpp"

using namespace lucent::optics;

namespace {
// 2 pi int_0^rho Rd(r) r dr by adaptive Simpson in t, r = s t/(1-t): the map sends [0, inf) to [0, 1),
// keeps the peak at r ~ z_r resolved, and leaves a finite integrand even for spectralon's 1/r^3 tail.
double numericIntegral(const DipoleChannel<double>& ch, double rho) {
  const double s = ch.zr;
  const double tMax = std::isinf(rho) ? 1.0 : rho / (rho + s);
  auto f = [&](double t) {
    if (t >= 1.0) {
      // Limit t -> 1 of 2 pi r Rd(r) dr/dt: nonzero only without absorption (1/r^3 tail).
      return ch.sigmaTr > 0 ? 0.0 : 2 * kPi * ch.alphaPrime / (4 * kPi) * (ch.zr + ch.zv) / s;
    }
    const double r = s * t / (1 - t), drdt = s / ((1 - t) * (1 - t));
    return 2 * kPi * r * ch.rd(r) * drdt;
  };
  // Split at the peak scale and at a few e-folding lengths so the adaptive steps see the structure.
  double sum = 0, a = 0;
  for (double b : {0.2, 0.5, 0.8, 0.95, 0.99, tMax}) {
    b = std::min(b, tMax);
    if (b > a) sum += lucent::test::integrate(f, a, b, 1e-13);
    a = b;
  }
  return sum;
}
}  // namespace

TEST_CASE("2 pi int Rd(r) r dr equals the total diffuse reflectance, for every measured material") {
  for (const auto& e : kMeasuredMaterials) {
    const Material m = toMaterial(e);
    const auto d = Dipole<double>::make(m.sigmaA, m.sigmaSPrime, m.eta);
    for (int c = 0; c < 3; ++c) {
      const double total = d.channel[c].total();
      const double numeric = numericIntegral(d.channel[c], std::numeric_limits<double>::infinity());
      INFO(m.name << " channel " << c << ": closed form " << total << ", numeric " << numeric);
      if (total < 1e-12) CHECK(std::abs(numeric) < 1e-12);
      else CHECK(numeric == doctest::Approx(total).epsilon(1e-4));
    }
  }
}

TEST_CASE("The closed-form cumulative profile matches numeric integration at finite radii") {
  for (const char* name : {"skin1", "marble", "spectralon", "ketchup"}) {
    const Material m = *findMaterial(name);
    const auto d = Dipole<double>::make(m.sigmaA, m.sigmaSPrime, m.eta);
    for (double rho : {0.01, 0.1, 1.0, 5.0, 30.0})
      for (int c = 0; c < 3; ++c) {
        INFO(name << " rho " << rho << " channel " << c);
        CHECK(d.channel[c].cumulative(rho) == doctest::Approx(numericIntegral(d.channel[c], rho)).epsilon(1e-6));
      }
  }
}

TEST_CASE("Rd at r = 0 and r -> infinity, and hard materials, are finite and non-negative") {
  const double radii[] = {0.0, 1e-9, 1e-3, 0.1, 1.0, 10.0, 1e4, 1e7, 1e12, std::numeric_limits<double>::max(),
                          std::numeric_limits<double>::infinity()};
  for (const auto& e : kMeasuredMaterials) {
    const Material m = toMaterial(e);
    for (double eta : {1.0, 1.3, 2.0, 2.5, 3.0}) {
      const auto d = Dipole<double>::make(m.sigmaA, m.sigmaSPrime, eta);
      const auto f = Dipole<float>::make(Rgb<float>(m.sigmaA), Rgb<float>(m.sigmaSPrime), float(eta));
      for (double r : radii) {
        const auto rd = d.rd(r);
        const auto rf = f.rd(float(std::min(r, double(std::numeric_limits<float>::max()))));
        for (int c = 0; c < 3; ++c) {
          INFO(m.name << " eta " << eta << " r " << r << " channel " << c);
          REQUIRE(std::isfinite(rd[c]));
          REQUIRE(rd[c] >= 0);
          REQUIRE(std::isfinite(rf[c]));
          REQUIRE(rf[c] >= 0);
        }
      }
      for (int c = 0; c < 3; ++c) {
        CHECK(std::isfinite(d.total()[c]));
        CHECK(d.total()[c] <= 1.0 + 1e-12);
        CHECK(std::isfinite(d.cumulative(1e30)[c]));
      }
    }
  }
}

TEST_CASE("Spectralon (sigma_a = 0): no exponential fall-off, all light comes back") {
  const Material m = *findMaterial("spectralon");
  const auto d = Dipole<double>::make(m.sigmaA, m.sigmaSPrime, m.eta);
  for (int c = 0; c < 3; ++c) {
    CHECK(d.channel[c].sigmaTr == 0);
    CHECK(d.channel[c].alphaPrime == 1);
    CHECK(d.channel[c].total() == doctest::Approx(1.0).epsilon(1e-12));
  }
  // Far away Rd falls as (alpha'/4pi)(zr + zv)/r^3.
  const double r = 1e4;
  CHECK(d.channel[0].rd(r) == doctest::Approx((d.channel[0].zr + d.channel[0].zv) / (4 * kPi * r * r * r)).epsilon(1e-6));
}

TEST_CASE("Objects from 0.01 mm to 10 m: Rd over the object's scale stays finite") {
  for (double size : {0.01, 1.0, 1e4}) {
    for (const char* name : {"skin1", "spectralon", "cream", "sprite"}) {
      const Material m = *findMaterial(name);
      const auto d = Dipole<float>::make(Rgb<float>(m.sigmaA), Rgb<float>(m.sigmaSPrime), float(m.eta));
      for (double f : {0.0, 1e-3, 0.1, 0.5, 1.0}) {
        const auto rd = d.rd(float(f * size));
        for (int c = 0; c < 3; ++c) {
          CHECK(std::isfinite(rd[c]));
          CHECK(rd[c] >= 0);
        }
      }
    }
  }
}

TEST_CASE("float agrees with double within 1e-5 relative wherever Rd is above float's underflow") {
  for (const auto& e : kMeasuredMaterials) {
    const Material m = toMaterial(e);
    const auto d = Dipole<double>::make(m.sigmaA, m.sigmaSPrime, m.eta);
    const auto f = Dipole<float>::make(Rgb<float>(m.sigmaA), Rgb<float>(m.sigmaSPrime), float(m.eta));
    for (double r = 0; r < 100; r = r * 1.3 + 0.001) {
      const auto rd = d.rd(r);
      const auto rf = f.rd(float(r));
      for (int c = 0; c < 3; ++c) {
        if (rd[c] < 1e-30) continue;
        INFO(m.name << " r " << r << " channel " << c);
        CHECK(double(rf[c]) == doctest::Approx(rd[c]).epsilon(1e-5));
      }
    }
  }
}

TEST_CASE("Zero scattering (clear liquids): alpha' = 0 gives Rd = 0, not NaN") {
  const auto d = DipoleChannel<double>::make(0.1, 0.0, 1.33);
  CHECK(d.alphaPrime == 0);
  CHECK(d.rd(0) == 0);
  CHECK(d.total() == 0);
  const auto none = DipoleChannel<double>::make(0.0, 0.0, 1.33);
  CHECK(none.rd(1.0) == 0);
  CHECK(std::isfinite(none.cumulative(1.0)));
}
