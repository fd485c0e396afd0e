#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include <lucent/optics/materials.hpp>
#include <lucent/optics/profile.hpp>
#include <lucent/reference/radial_table_sum.hpp>

using namespace lucent;

namespace {
/// Samples scattered over a 30 mm cube, with weights of three magnitudes.
reference::GatheredSamples randomSamples(std::size_t n) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> position(-15, 15), weight(0, 1);
  reference::GatheredSamples s;
  s.fit(n);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec3 x(position(rng), position(rng), position(rng));
    s.set(i, x, glm::vec3(weight(rng), 0.1f * weight(rng), 0.01f * weight(rng)));
  }
  return s;
}

/// Skin's dipole as a radial table on [0, 40 mm], as tsis builds it.
optics::RadialTable<float> skinTable() {
  const optics::Material m = *optics::findMaterial("skin1");
  const auto d = optics::Dipole<float>::make(optics::Rgb<float>(m.sigmaA),
                                             optics::Rgb<float>(m.sigmaSPrime), float(m.eta));
  return optics::RdTable<float>(d, 40.0f);
}
}  // namespace

TEST_CASE("Radial-table sum: equals the table's own lookup summed in double, every tail length") {
  const auto table = skinTable();
  const reference::PlanarRadialTable planar(table);
  const auto samples = randomSamples(3000);
  const float origin[3] = {1.5f, -2.0f, 0.25f};
  for (std::size_t n : {0, 1, 15, 16, 17, 1023, 1024, 1025, 3000}) {
    CAPTURE(n);
    double out[3];
    reference::radialTableSum(samples.view(n), planar, origin[0], origin[1], origin[2], out);
    double expect[3] = {0, 0, 0};
    for (std::size_t i = 0; i < n; ++i) {
      const double dx = samples.array[0][i] - origin[0], dy = samples.array[1][i] - origin[1],
                   dz = samples.array[2][i] - origin[2];
      const auto v = table(float(std::sqrt(dx * dx + dy * dy + dz * dz)));
      for (int c = 0; c < 3; ++c) expect[c] += double(samples.array[3 + c][i]) * v[c];
    }
    for (int c = 0; c < 3; ++c) CHECK(out[c] == doctest::Approx(expect[c]).epsilon(1e-4));
  }
}

TEST_CASE("Radial-table sum: the AVX-512 record path equals the per-channel gathers") {
#if LUCENT_HAS_AVX512_TABLE_SUM
  if (!reference::cpuHasAvx512()) {
    MESSAGE("this CPU has no AVX-512: the record path is not run here");
    return;
  }
  const reference::PlanarRadialTable planar(skinTable());
  const auto samples = randomSamples(3000);
  // An origin on a sample (r = 0, node 0), inside, near and beyond the table's end (rMax = 40 mm).
  const float origins[][3] = {{samples.array[0][5], samples.array[1][5], samples.array[2][5]},
                              {0.5f, 0.25f, -1.0f},
                              {30.0f, 0.0f, 0.0f},
                              {200.0f, 0.0f, 0.0f}};
  for (const auto& o : origins)
    for (std::size_t n : {16, 17, 31, 1024, 1040, 3000}) {
      CAPTURE(n);
      CAPTURE(o[0]);
      double records[3] = {0, 0, 0}, gathered[3] = {0, 0, 0};
      const std::size_t done = reference::radialTableSumAvx512(
          samples.view(n), planar.nodes.data(), int(planar.size()) - 1, planar.lookupScale(), o[0],
          o[1], o[2], records);
      CHECK(done == n - n % 16);
      reference::radialTableSumGathered(samples.view(done), planar, o[0], o[1], o[2], 0, done,
                                        gathered);
      for (int c = 0; c < 3; ++c) {
        CHECK(std::isfinite(records[c]));
        CHECK(records[c] == doctest::Approx(gathered[c]).epsilon(1e-5));
      }
    }
#else
  MESSAGE("no AVX-512 path in this build");
#endif
}
