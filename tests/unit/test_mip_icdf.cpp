#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include <lucent/atlas/mip_icdf.hpp>

using namespace lucent::atlas;

namespace {
// An irregular image with zero rows, zero texels, and non-power-of-two size: the hard case for both ICDFs.
std::vector<float> testImage(int w, int h) {
  std::vector<float> v(std::size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float value = float(1 + std::sin(0.7 * x) * std::cos(0.45 * y)) * float(1 + x % 3);
      if (y == 2 || (x + y) % 5 == 0) value = 0;
      v[std::size_t(y) * w + x] = value;
    }
  return v;
}

// Pearson's chi-square of sample counts against N p, with the Wilson-Hilferty normal approximation of
// its upper tail; z > 3.1 means p < 0.001. Bins with an expected count below 5 are pooled.
template <class Sampler>
double chiSquareZ(const Sampler& sampler, const std::vector<float>& v, int w, std::size_t n, std::uint32_t seed) {
  std::vector<double> counts(v.size(), 0.0);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  double total = 0;
  for (float x : v) total += x;
  for (std::size_t i = 0; i < n; ++i) {
    const auto s = sampler.sample(u(rng), u(rng));
    REQUIRE(s.has_value());
    const float value = v[std::size_t(s->y) * w + s->x];
    REQUIRE(value > 0);  // never a zero texel
    CHECK(s->probability == doctest::Approx(value / total).epsilon(1e-9));
    CHECK(s->u >= s->x);
    CHECK(s->u < s->x + 1);
    counts[std::size_t(s->y) * w + s->x] += 1;
  }
  double chi2 = 0, pooledObserved = 0, pooledExpected = 0;
  int bins = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double expected = double(n) * v[i] / total;
    if (expected < 5) {
      pooledObserved += counts[i], pooledExpected += expected;
      continue;
    }
    chi2 += (counts[i] - expected) * (counts[i] - expected) / expected;
    ++bins;
  }
  if (pooledExpected >= 5) {
    chi2 += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
    ++bins;
  }
  const double k = bins - 1;
  return (std::cbrt(chi2 / k) - (1 - 2 / (9 * k))) / std::sqrt(2 / (9 * k));
}
}  // namespace

TEST_CASE("Both ICDFs draw texels in proportion to their value (chi-square), never a zero texel") {
  const int w = 13, h = 7;
  const std::vector<float> v = testImage(w, h);
  const MipIcdf mip(w, h, v);
  const RowIcdf row(w, h, v);
  const double zMip = chiSquareZ(mip, v, w, 200000, 1), zRow = chiSquareZ(row, v, w, 200000, 2);
  INFO("chi-square z: mip " << zMip << ", row " << zRow);
  CHECK(zMip < 3.1);
  CHECK(zRow < 3.1);
  CHECK(mip.levels() == 5);  // 13 -> padded to 16: 1, 2, 4, 8, 16
}

TEST_CASE("A wrong distribution is caught: the chi-square test can fail") {
  const int w = 13, h = 7;
  const std::vector<float> v = testImage(w, h);
  std::vector<float> skewed = v;
  for (std::size_t i = 0; i < skewed.size(); i += 2) skewed[i] *= 1.5f;
  const MipIcdf wrong(w, h, skewed);
  // Sampling the skewed image but testing against the original must fail loudly.
  std::vector<double> counts(v.size(), 0.0);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  double total = 0, chi2 = 0;
  for (float x : v) total += x;
  for (int i = 0; i < 200000; ++i) {
    const auto s = wrong.sample(u(rng), u(rng));
    counts[std::size_t(s->y) * w + s->x] += 1;
  }
  for (std::size_t i = 0; i < v.size(); ++i)
    if (v[i] > 0) chi2 += std::pow(counts[i] - 200000 * v[i] / total, 2) / (200000 * v[i] / total);
  CHECK(chi2 > 1000);
}

TEST_CASE("All-zero irradiance (light behind the object) samples nothing instead of dividing by zero") {
  const std::vector<float> zero(64, 0.0f);
  CHECK_FALSE(MipIcdf(8, 8, zero).sample(0.3, 0.7).has_value());
  CHECK_FALSE(RowIcdf(8, 8, zero).sample(0.3, 0.7).has_value());
  std::vector<float> nan(64, std::nanf(""));
  nan[10] = 2.0f;  // one valid texel among NaNs: it is the only one ever drawn
  const auto s = MipIcdf(8, 8, nan).sample(0.9, 0.1);
  REQUIRE(s.has_value());
  CHECK(s->x == 2);
  CHECK(s->y == 1);
  CHECK(s->probability == 1.0);
  CHECK_THROWS(MipIcdf(4, 4, std::vector<float>(3)));
}

TEST_CASE("Stratified inputs through the mip warp reduce the variance of the importance-sampled estimate") {
  // Estimate I = sum_texels g(texel) with g / p. Jittered k x k inputs, warped hierarchically, against
  // independent inputs: same sampler, same sample count.
  const int w = 32, h = 32;
  std::vector<float> v(std::size_t(w) * h);
  std::vector<double> g(v.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      v[std::size_t(y) * w + x] = float(1 + 0.8 * std::sin(0.3 * x) * std::sin(0.2 * y));
      g[std::size_t(y) * w + x] = v[std::size_t(y) * w + x] * (1 + 0.5 * std::cos(0.25 * x + 0.1 * y));
    }
  const MipIcdf mip(w, h, v);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  const int k = 16, trials = 300;
  auto variance = [&](bool stratified) {
    double sum = 0, sumSq = 0;
    for (int t = 0; t < trials; ++t) {
      double est = 0;
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
          const double a = stratified ? (i + u(rng)) / k : u(rng), b = stratified ? (j + u(rng)) / k : u(rng);
          const auto s = mip.sample(a, b);
          est += g[std::size_t(s->y) * w + s->x] / s->probability;
        }
      est /= k * k;
      sum += est, sumSq += est * est;
    }
    return sumSq / trials - (sum / trials) * (sum / trials);
  };
  const double independent = variance(false), stratified = variance(true);
  INFO("variance independent " << independent << ", stratified " << stratified << ", ratio " << independent / stratified);
  CHECK(stratified < 0.5 * independent);
}
