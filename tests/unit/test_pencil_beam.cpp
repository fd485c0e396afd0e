#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include <lucent/reference/pencil_beam_mc.hpp>

using namespace lucent;

namespace {
// Gauss-Legendre nodes and weights on [0, 1] (Newton on P_n), for the H-function quadrature.
void gaussLegendre01(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(std::size_t(n), 0);
  w.assign(std::size_t(n), 0);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(optics::kPi * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1, p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-15) break;
    }
    x[std::size_t(i)] = 0.5 * (1 - z);
    w[std::size_t(i)] = 1.0 / ((1 - z * z) * dp * dp);  // 2/((1-z^2) P'^2), halved for [0,1]
  }
}

// Chandrasekhar's H-function for isotropic scattering with single-scattering albedo a, by fixed-point
// iteration of 1/H(mu) = sqrt(1-a) + (a/2) int_0^1 mu' H(mu') / (mu + mu') dmu' (Chandrasekhar 1960,
// Radiative Transfer, the form that converges for every a < 1).
double chandrasekharH(double mu, double a) {
  std::vector<double> x, w;
  gaussLegendre01(48, x, w);
  std::vector<double> h(x.size(), 1.0);
  auto evaluate = [&](double m) {
    double s = 0;
    for (std::size_t j = 0; j < x.size(); ++j) s += w[j] * x[j] * h[j] / (m + x[j]);
    return 1.0 / (std::sqrt(1 - a) + 0.5 * a * s);
  };
  for (int it = 0; it < 2000; ++it) {
    std::vector<double> next(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) next[i] = evaluate(x[i]);
    h.swap(next);
  }
  return evaluate(mu);
}
}  // namespace

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
