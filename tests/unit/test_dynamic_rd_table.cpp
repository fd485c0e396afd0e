#include <doctest/doctest.h>

#include <cmath>

#include <lucent/atlas/dynamic_rd_table.hpp>

#include "quadrature.hpp"

using namespace lucent;

namespace {
/// Largest relative error of the table against the direct profile, at t halfway between rows, over
/// distances where the profile is at least 1e-3 of its peak.
double midRowError(const atlas::DynamicRdTable& table) {
  double worst = 0;
  for (std::size_t j = 0; j + 1 < table.rows(); ++j) {
    const double t = (double(j) + 0.5) / double(table.rows() - 1);
    const auto peak = table.exact(0, t);
    for (double r = 0; r <= 5; r += 0.01) {
      const auto e = table.exact(r, t), a = table(r, t);
      for (int c = 0; c < 3; ++c)
        if (e[c] >= 1e-3 * peak[c]) worst = std::max(worst, std::abs(a[c] / e[c] - 1));
    }
  }
  return worst;
}
}  // namespace

TEST_CASE(
    "Dynamic Rd table (Sec. 5.1): skin1 -> marble, 10 -> 30 mm, error falls as rows are added") {
  const auto a = atlas::settingOf(*optics::findMaterial("skin1"), 1.0);
  const auto b = atlas::settingOf(*optics::findMaterial("marble"), 3.0);
  std::vector<double> errors;
  for (std::size_t rows : {4, 8, 16, 64})
    errors.push_back(midRowError(atlas::DynamicRdTable(a, b, 20.0, rows, 4096)));
  INFO("mid-row relative error at 4, 8, 16, 64 rows: " << errors[0] << " " << errors[1] << " "
                                                       << errors[2] << " " << errors[3]);
  // Linear interpolation in t of an exponential tail: second order only once rows resolve the decay
  // rate's change (measured 1.09, 0.43, 0.17, 0.020: 8.5x from 16 to 64 rows).
  CHECK(errors[1] < errors[0] / 2);
  CHECK(errors[2] < errors[1] / 2);
  CHECK(errors[3] < errors[2] / 6);
  CHECK(errors[3] < 0.025);
}

TEST_CASE("Dynamic Rd table: the k^2 factor keeps total reflectance under scaling") {
  // Same material, twice the size: int_0^R T(r, 1) 2 pi r dr = int_0^{2R} Rd(r) 2 pi r dr (r ->
  // 2r).
  const auto m = atlas::settingOf(*optics::findMaterial("ketchup"), 1.0);
  auto big = m;
  big.sizeScale = 2.0;
  const atlas::DynamicRdTable table(m, big, 10.0, 8, 8192);
  const auto d = optics::Dipole<double>::make(m.sigmaA, m.sigmaSPrime, m.eta);
  for (int c = 0; c < 3; ++c) {
    const double integral = test::integrate(
        [&](double r) { return table.exact(r, 1.0)[c] * 2 * optics::kPi * r; }, 0, 4.0, 1e-12);
    CHECK(integral == doctest::Approx(d.channel[c].cumulative(8.0)).epsilon(1e-6));
    const double tabulated = test::integrate(
        [&](double r) { return table(r, 1.0)[c] * 2 * optics::kPi * r; }, 0, 4.0, 1e-10);
    CHECK(tabulated == doctest::Approx(d.channel[c].cumulative(8.0)).epsilon(2e-3));
  }
  CHECK(table(11.0, 0.5) == optics::Rgb<double>(0));
  CHECK_THROWS(atlas::DynamicRdTable(m, big, 0.0));
}
