#include <doctest/doctest.h>

#include <algorithm>
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

/// |a - b| <= tol max(|a|, |b|): relative at every magnitude (doctest's Approx adds 1 to the scale,
/// which makes it absolute for the small sums of the weak channels).
bool relativelyClose(double a, double b, double tol) {
  return a == b || std::abs(a - b) <= tol * std::max(std::abs(a), std::abs(b));
}

/// A table that is (1, 2, 3) everywhere on [0, 10 mm]: nonzero at rMax, so a term beyond it counts
/// only if the mask is wrong.
optics::RadialTable<float> constantTable() {
  return optics::RadialTable<float>([](float) { return optics::Rgb<float>(1, 2, 3); }, 10.0f);
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
    for (int c = 0; c < 3; ++c) CHECK(relativelyClose(out[c], expect[c], 1e-4));
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
        CHECK(relativelyClose(records[c], gathered[c], 1e-5));
      }
    }
#else
  MESSAGE("no AVX-512 path in this build");
#endif
}

TEST_CASE("Radial-table sum: terms beyond rMax and at NaN positions add nothing, on every path") {
  const reference::PlanarRadialTable planar(constantTable());
  // 32 terms (two AVX-512 blocks of 16) and 7 more for the gathered tail: distances 0-9 mm count,
  // 11-50 mm and NaN do not.
  reference::GatheredSamples s;
  const std::size_t n = 39;
  s.fit(n);
  double expect = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const int kind = int(i % 3);  // 0 inside, 1 beyond, 2 NaN
    const float r = kind == 0 ? 0.3f * float(i % 30) : 11.0f + float(i);
    const float x = kind == 2 ? std::nanf("") : r;
    const float w = 1.0f + float(i);
    s.set(i, glm::vec3(x, 0, 0), glm::vec3(w, w, w));
    if (kind == 0) expect += w;
  }
  double out[3];
  reference::radialTableSum(s.view(n), planar, 0, 0, 0, out);
  for (int c = 0; c < 3; ++c) CHECK(out[c] == doctest::Approx(expect * (c + 1)));
  double gathered[3] = {0, 0, 0};
  reference::radialTableSumGathered(s.view(n), planar, 0, 0, 0, 0, n, gathered);
  for (int c = 0; c < 3; ++c) CHECK(gathered[c] == doctest::Approx(expect * (c + 1)));
}

#if LUCENT_HAS_AVX512_TABLE_SUM
namespace {
/// loadNodes16's six vectors, stored lane by lane.
__attribute__((target("avx512f,avx512dq,fma"))) void transposed(
    const reference::RadialTableNode* nodes, const int k[16], float value[3][16],
    float slope[3][16]) {
  __m512 v[3], d[3];
  reference::detail::loadNodes16(nodes, k, v, d);
  for (int c = 0; c < 3; ++c) _mm512_storeu_ps(value[c], v[c]), _mm512_storeu_ps(slope[c], d[c]);
}
}  // namespace

TEST_CASE("Radial-table sum: the record transposition puts term i's field j in lane i, exactly") {
  if (!reference::cpuHasAvx512()) {
    MESSAGE("this CPU has no AVX-512: the transposition is not run here");
    return;
  }
  // Node k's field j is 8k + j: every lane names the node and field it came from.
  std::vector<reference::RadialTableNode> nodes(40);
  for (int k = 0; k < 40; ++k)
    for (int c = 0; c < 3; ++c)
      nodes[k].value[c] = float(8 * k + c), nodes[k].slope[c] = float(8 * k + 3 + c);
  const int k[16] = {39, 0, 7, 7, 12, 3, 38, 21, 5, 30, 1, 17, 26, 9, 33, 14};  // repeats, unsorted
  float value[3][16], slope[3][16];
  transposed(nodes.data(), k, value, slope);
  for (int lane = 0; lane < 16; ++lane)
    for (int c = 0; c < 3; ++c) {
      CAPTURE(lane);
      CAPTURE(c);
      CHECK(value[c][lane] == float(8 * k[lane] + c));
      CHECK(slope[c][lane] == float(8 * k[lane] + 3 + c));
    }
}
#endif
