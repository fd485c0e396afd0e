#include <doctest/doctest.h>

#include <cmath>

#include <lucent/atlas/hybrid.hpp>
#include <lucent/atlas/ring_filter.hpp>
#include <lucent/optics/materials.hpp>
#include <lucent/reference/radial_table_sum.hpp>

using namespace lucent;

namespace {
optics::Dipole<double> dipoleOf(const char* name) {
  const optics::Material m = *optics::findMaterial(name);
  return optics::Dipole<double>::make(m.sigmaA, m.sigmaSPrime, m.eta);
}
}  // namespace

TEST_CASE(
    "Ring filter: strata hold equal importance, masses sum to the covered share of int f 2 pi r") {
  for (const char* name : {"skin1", "marble", "ketchup", "spectralon"}) {
    CAPTURE(name);
    const auto d = dipoleOf(name);
    const double domain = 100;
    auto rd = [&](double r) { return glm::dvec3(d.rd(r)); };
    const auto ring = atlas::makeRingFilter(rd, 16, 8, domain, 0.999);
    REQUIRE(ring.sampleCount() == 16 * 8 + 1);
    CHECK(ring.radius[0] == 0);
    for (std::size_t k = 1; k < ring.radius.size(); ++k) CHECK(ring.radius[k] > ring.radius[k - 1]);
    // Sum of masses = closed-form cumulative at the outer radius (dipole.hpp's CDF, independent of
    // the filter's own trapezoid), to the filter's quadrature accuracy.
    glm::dvec3 sum(0);
    for (const auto& m : ring.mass) sum += m;
    const auto exact = d.cumulative(ring.outerRadius);
    for (int c = 0; c < 3; ++c) CHECK(sum[c] == doctest::Approx(exact[c]).epsilon(2e-3));
    // Flat, uniformly lit surface: every sample sees |x - x_o| = r_k, so the filter returns
    // rho * sum of masses exactly: the ratio estimator is exact there.
    for (std::size_t k = 0; k < ring.radius.size(); ++k)
      for (int c = 0; c < 3; ++c)
        CHECK(ring.profileAt[k][c] == doctest::Approx(d.rd(ring.radius[k])[c]));
  }
}

TEST_CASE("Ring filter: nothing scatters -> an empty filter, no NaN") {
  const auto ring = atlas::makeRingFilter([](double) { return glm::dvec3(0); }, 4, 4, 10.0);
  for (const auto& m : ring.mass) CHECK(m == glm::dvec3(0));
  CHECK_THROWS(atlas::makeRingFilter([](double) { return glm::dvec3(1); }, 0, 4, 10.0));
}

TEST_CASE(
    "Ring filter: the centre's disc transfer is 1 at d = 0, falls with d, and is the closed form "
    "of an exponential profile, and keeps its mass for a profile singular at 0") {
  // f_c = e^{-s_c r}: C(r) = int_0^r f 2 pi r dr = 2 pi (1 - e^{-s r} (1 + s r)) / s^2, typed here.
  const glm::dvec3 sigma(0.5, 2.0, 8.0);
  const auto f = [&](double r) { return glm::exp(-sigma * r); };
  const auto filter = lucent::atlas::makeRingFilter(f, 8, 8, 40.0);
  const auto closed = [&](double r, int c) {
    const double s = sigma[c];
    return 2 * M_PI * (1 - std::exp(-s * r) * (1 + s * r)) / (s * s);
  };
  const double r0 = filter.innerRadius;
  REQUIRE(r0 > 0);
  glm::dvec3 previous(1.0);
  for (const double d : {0.0, 0.01, 0.1, 0.3, 1.0, 3.0, 10.0}) {
    const glm::dvec3 t = filter.centreTransfer(d);
    for (int c = 0; c < 3; ++c) {
      INFO("d " << d << " channel " << c);
      const double want = (closed(std::hypot(r0, d), c) - closed(d, c)) / closed(r0, c);
      CHECK(t[c] == doctest::Approx(want).epsilon(2e-3));
      CHECK(t[c] <= previous[c] + 1e-12);
    }
    if (d == 0) CHECK(t == glm::dvec3(1.0));
    previous = t;
  }
  // A 1/r profile held below 1e-4 (as pbd and Burley are): the disc keeps its mass at d = 0.
  const auto singular = lucent::atlas::makeRingFilter(
      [](double r) { return glm::dvec3(1.0 / std::max(r, 1e-4)); }, 8, 8, 10.0);
  CHECK(singular.centreTransfer(0.0) == glm::dvec3(1.0));
  const glm::dvec3 half = singular.centreTransfer(0.5 * singular.innerRadius);
  // 1/r: T(d) = (sqrt(R^2 + d^2) - d) / R = sqrt(1.25) - 0.5 at d = R / 2.
  CHECK(half.x == doctest::Approx(std::sqrt(1.25) - 0.5).epsilon(2e-3));
}

TEST_CASE("Hybrid profiles: Rd Wl + Rd Wg = Rd within the tables' bounds, for every material") {
  for (const auto& entry : optics::kMeasuredMaterials) {
    const optics::Material m = optics::toMaterial(entry);
    CAPTURE(m.name);
    const auto d = optics::Dipole<double>::make(m.sigmaA, m.sigmaSPrime, m.eta);
    const double rp = atlas::hybridRp(d, 0.05);
    const atlas::HybridProfiles p(d, rp, 50.0);
    const auto peak = d.rd(0.0);
    for (double r = 0; r <= 50; r += 0.0137) {
      const auto sum = p.local(float(r)) + p.global(float(r));
      for (int c = 0; c < 3; ++c)
        REQUIRE(std::abs(sum[c] - d.rd(r)[c]) <=
                2e-3 * std::max(d.rd(r)[c], 1e-6 * peak[c]) + 1e-6 * d.rd(r)[c] + 1e-30);
    }
  }
}

TEST_CASE("Table sum kernel equals the scalar table lookup, and is 0 beyond rMax") {
  const auto d = optics::Dipole<float>::make(optics::Rgb<float>(0.032f, 0.17f, 0.48f),
                                             optics::Rgb<float>(0.74f, 0.88f, 1.01f), 1.3f);
  const optics::RdTable<float> table(d, 20.0f);
  const reference::PlanarRadialTable planar(table);
  std::vector<float> x, y, z, w0, w1, w2;
  for (int i = 0; i < 3000; ++i) {
    const float t = float(i) * 0.01f;
    x.push_back(std::sin(t) * t), y.push_back(std::cos(1.3f * t)), z.push_back(0.1f * t);
    w0.push_back(1.0f + 0.1f * float(i % 7)), w1.push_back(0.5f), w2.push_back(float(i % 3));
  }
  const reference::RdKernelSamples s{x.data(),  y.data(),  z.data(), w0.data(),
                                     w1.data(), w2.data(), x.size()};
  double out[3];
  reference::radialTableSum(s, planar, 0.3f, -0.2f, 1.0f, out);
  double expect[3] = {0, 0, 0};
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double dx = x[i] - 0.3, dy = y[i] + 0.2, dz = z[i] - 1.0;
    const auto v = table(float(std::sqrt(dx * dx + dy * dy + dz * dz)));
    expect[0] += w0[i] * v[0], expect[1] += w1[i] * v[1], expect[2] += w2[i] * v[2];
  }
  for (int c = 0; c < 3; ++c) CHECK(out[c] == doctest::Approx(expect[c]).epsilon(1e-4));
  // All samples beyond rMax: exactly zero.
  for (auto& v : x) v += 100.0f;
  reference::radialTableSum(s, planar, 0, 0, 0, out);
  for (double v : out) CHECK(v == 0.0);
}
