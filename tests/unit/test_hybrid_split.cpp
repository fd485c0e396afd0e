#include <doctest/doctest.h>

#include <cmath>

#include <lucent/atlas/hybrid_split.hpp>
#include <lucent/optics/materials.hpp>

using namespace lucent;

TEST_CASE("Wl + Wg = 1, Wl is continuous (0.5 at Rp), in [0, 1], near 1 at 0 and vanishing far away") {
  for (double rp : {0.5, 2.4141, 10.0}) {
    CHECK(atlas::localWeight(rp, rp) == doctest::Approx(0.5));
    CHECK(atlas::localWeight(rp * (1 + 1e-12), rp) == doctest::Approx(0.5));
    for (double r = 0; r < 5 * rp; r += rp / 50) {
      const double wl = atlas::localWeight(r, rp);
      CHECK(wl >= 0);
      CHECK(wl <= 1);
      CHECK(wl + atlas::globalWeight(r, rp) == doctest::Approx(1.0));
    }
    CHECK(atlas::localWeight(rp + 20, rp) < 1e-12);
  }
  CHECK(atlas::localWeight(0, 10) > 0.9999);
}

TEST_CASE("Rp is the largest radius where Rd(r) 2 pi r meets the bound c, for every measured material") {
  for (const auto& e : optics::kMeasuredMaterials) {
    const optics::Material m = optics::toMaterial(e);
    const auto d = optics::Dipole<double>::make(m.sigmaA, m.sigmaSPrime, m.eta);
    for (double c : {1e-3, 1e-2, 0.1}) {
      const double rp = atlas::hybridRp(d, c);
      INFO(m.name << " c " << c << " Rp " << rp);
      REQUIRE(std::isfinite(rp));
      if (rp == 0) {  // no channel reaches c: everything is global
        for (const auto& ch : d.channel)
          for (double r = 1e-4; r < 100; r *= 1.1) CHECK(atlas::importance(ch, r) < c);
        continue;
      }
      double best = 0;
      for (const auto& ch : d.channel) best = std::max(best, atlas::importance(ch, rp));
      CHECK(best == doctest::Approx(c).epsilon(1e-6));
      for (const auto& ch : d.channel)  // beyond Rp every channel stays below c
        for (double r = rp * 1.001; r < 20 * rp; r *= 1.05) CHECK(atlas::importance(ch, r) < c);
    }
  }
}

TEST_CASE("Spectralon (1/r^2 importance tail) and a bound above the peak terminate with finite Rp") {
  const optics::Material s = *optics::findMaterial("spectralon");
  const auto d = optics::Dipole<double>::make(s.sigmaA, s.sigmaSPrime, s.eta);
  const double rp = atlas::hybridRp(d, 1e-4);
  CHECK(std::isfinite(rp));
  // Far out, alpha' = 1 and sigma_tr = 0 leave importance = (zr + zv) / (2 r^2): Rp = sqrt((zr+zv)/(2c)).
  double analytic = 0;
  for (const auto& ch : d.channel) analytic = std::max(analytic, std::sqrt((ch.zr + ch.zv) / (2 * 1e-4)));
  CHECK(rp == doctest::Approx(analytic).epsilon(1e-3));
  CHECK(atlas::hybridRp(d, 1e6) == 0);
  CHECK_THROWS(atlas::hybridRp(d, 0.0));
}
