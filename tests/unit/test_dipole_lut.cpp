#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <lucent/optics/dipole_lut.hpp>
#include <lucent/optics/materials.hpp>
#include <lucent/optics/profile.hpp>

using namespace lucent::optics;

namespace {
// The bound of RdTableBound, checked densely (not only at the midpoints the table was refined on).
// From the profile's regularFrom on (0 for the dipoles).
void checkBound(const Profile<double>& d, double rMax, RdTableBound<double> bound,
                const std::string& name) {
  const RadialTable<double> table = radialTable(d, rMax, bound);
  INFO(name << " rMax " << rMax << ": " << table.size() << " nodes");
  REQUIRE_FALSE(table.saturated());
  const auto r0 = d.regularFrom();
  for (int c = 0; c < 3; ++c) {  // a held core only where a singular profile scatters
    const bool held = !d.isPolePair() && d.channel[c].scatters();
    CHECK(r0[c] == doctest::Approx(held ? 1e-3 * d.channel[c].meanFreePath() : 0.0));
  }
  glm::dvec3 peak;
  for (int c = 0; c < 3; ++c) peak[c] = d.rd(r0[c])[c];
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0;
  for (int i = 0; i < 200000; ++i) {
    const double s = u(rng);
    const double r = rMax * s * s;  // as dense near 0 as the table itself
    const auto exact = d.rd(r), approx = table(r);
    for (int c = 0; c < 3; ++c) {
      if (r < r0[c]) continue;
      const double allowed = bound.relTol * std::max(exact[c], bound.floor * peak[c]);
      if (allowed > 0)
        worst = std::max(worst, std::abs(approx[c] - exact[c]) / allowed);
      else
        CHECK(approx[c] == 0);
    }
  }
  INFO("worst error / bound = " << worst);
  CHECK(worst <= 1.0);
}
void checkBound(const Material& m, double rMax, RdTableBound<double> bound) {
  checkBound(Dipole<double>::make(m.sigmaA, m.sigmaSPrime, m.eta), rMax, bound, m.name);
}
}  // namespace

TEST_CASE("The Rd table meets its stated error bound for every measured material") {
  for (const auto& e : kMeasuredMaterials) checkBound(toMaterial(e), 30.0, {1e-3, 1e-6});
}

TEST_CASE("The Rd table meets tighter bounds, on tiny and huge ranges, for the hard materials") {
  for (const char* name : {"skin1", "spectralon", "cream", "ketchup"})
    for (double rMax : {0.01, 1.0, 10000.0}) checkBound(*findMaterial(name), rMax, {1e-4, 1e-5});
}

TEST_CASE(
    "Every profile's table meets the bound from its regularFrom on, for every measured material, "
    "and the core below it holds at most 0.5 % of the light") {
  for (const auto& info : kProfileModels)
    for (const auto& e : kMeasuredMaterials) {
      const Material m = toMaterial(e);
      const auto p = Profile<double>::make(info.model, m.sigmaA, m.sigmaSPrime, m.eta);
      checkBound(p, 30.0, {1e-3, 1e-6}, std::string(info.name) + " " + m.name);
      // The core the bound leaves out: a 1/r profile leaves r0 / l of its light inside r0.
      const auto r0 = p.regularFrom();
      const auto total = p.total();
      for (int c = 0; c < 3; ++c) {
        INFO(info.name << " " << m.name << " channel " << c);
        CHECK(p.channel[c].cumulative(r0[c]) <= 0.005 * total[c]);
      }
    }
}

TEST_CASE("The Rd table returns 0 beyond rMax and for negative or NaN distances") {
  const auto d = Dipole<double>::make(Rgb<double>(0.032), Rgb<double>(0.74), 1.3);
  const RdTable<double> table(d, 10.0);
  CHECK(table(10.5).x == 0);
  CHECK(table(-1.0).x == 0);
  CHECK(table(std::nan("")).x == 0);
  CHECK(table(10.0).x == doctest::Approx(d.rd(10.0).x).epsilon(1e-3));
  CHECK_THROWS(RdTable<double>(d, 0.0));
  CHECK_THROWS(RdTable<double>(d, std::nan("")));
}
