#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include <lucent/reference/pencil_beam_mc.hpp>

#include "chandrasekhar_h.hpp"

using namespace lucent;

using test::chandrasekharH;
using test::gaussLegendre01;

TEST_CASE("The H-function solver satisfies the exact moment identity int_0^1 H = (2/a)(1 - sqrt(1-a))") {
  // Chandrasekhar (1960), the zeroth moment of H: a check of the solver independent of its iteration.
  std::vector<double> x, w;
  gaussLegendre01(64, x, w);
  for (double a : {0.3, 0.5, 0.9, 0.99}) {
    double moment = 0;
    for (std::size_t i = 0; i < x.size(); ++i) moment += w[i] * chandrasekharH(x[i], a);
    CHECK(moment == doctest::Approx(2 / a * (1 - std::sqrt(1 - a))).epsilon(1e-6));
  }
}

TEST_CASE("Index-matched isotropic half-space: reflected fraction = 1 - H(1) sqrt(1 - albedo)") {
  for (double albedo : {0.5, 0.9, 0.99}) {
    reference::PencilBeamSettings s;
    s.sigmaS = albedo;
    s.sigmaA = 1 - albedo;
    s.g = 0;
    s.eta = 1.0;
    s.photons = 200000;
    s.seed = 7;
    const reference::RadialProfile p = reference::simulatePencilBeam(s);
    const double exact = 1 - chandrasekharH(1.0, albedo) * std::sqrt(1 - albedo);
    INFO("albedo " << albedo << ": MC " << p.total << " +- " << p.totalStdError << ", exact " << exact);
    CHECK(std::abs(p.total - exact) < 4 * p.totalStdError);
    CHECK(p.droppedPhotons == 0);
  }
}

TEST_CASE("Pencil beam: the rings sum to the escapes within rMax, results repeat for a fixed seed") {
  reference::PencilBeamSettings s;
  s.sigmaA = 0.032;
  s.sigmaS = 0.74;
  s.photons = 20000;
  s.rMax = 1000;  // everything escapes within it
  s.rings = 50;
  const auto a = reference::simulatePencilBeam(s), b = reference::simulatePencilBeam(s, [](std::size_t n, const util::RangeBody& body) {
    for (std::size_t i = n; i-- > 0;) body(i, i + 1);  // another order of blocks
  });
  double ringSum = 0;
  for (std::size_t i = 0; i < a.rd.size(); ++i) {
    ringSum += a.rd[i] * optics::kPi * (a.rOuter[i] * a.rOuter[i] - a.rInner[i] * a.rInner[i]);
    CHECK(a.rd[i] == b.rd[i]);
    CHECK(std::isfinite(a.rdStdError[i]));
  }
  CHECK(ringSum == doctest::Approx(a.total).epsilon(1e-12));
  CHECK(a.total == b.total);
  CHECK(a.total > 0);
  CHECK(a.total < 1);
}
