// Haar wavelets for PRT: orthonormal, exact inverse, Parseval, and a non-linear approximation whose
// error is the energy it drops; quantisation within its stated bound.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <lucent/prt/haar.hpp>
#include <lucent/prt/sparse_vector.hpp>

using namespace lucent::prt;

namespace {
std::vector<double> randomImage(int n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  std::vector<double> v(std::size_t(n) * n);
  for (double& x : v) x = g(rng);
  return v;
}
std::vector<glm::vec3> randomCube(int size, std::uint32_t seed, double sparsity) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<glm::vec3> v(std::size_t(6) * size * size);
  for (auto& c : v)  // a smooth part and a few bright texels (an all-frequency light)
    c = glm::vec3(float(0.5 + 0.1 * u(rng))) +
        (u(rng) < sparsity ? glm::vec3(50, 40, 30) : glm::vec3(0));
  return v;
}
}  // namespace

TEST_CASE("The 2-D Haar transform is orthonormal: its basis images are orthonormal") {
  const int n = 8;
  std::vector<std::vector<double>> rows;
  for (int i = 0; i < n * n; ++i) {  // the transform of each unit image is a row of W
    std::vector<double> e(std::size_t(n) * n, 0.0);
    e[std::size_t(i)] = 1;
    haarForward(e.data(), n);
    rows.push_back(e);
  }
  double worst = 0;
  for (int a = 0; a < n * n; ++a)
    for (int b = 0; b < n * n; ++b) {
      double d = 0;
      for (int k = 0; k < n * n; ++k) d += rows[a][k] * rows[b][k];
      worst = std::max(worst, std::abs(d - (a == b ? 1.0 : 0.0)));
    }
  CHECK(worst < 1e-12);
  // The scaling coefficient of a constant image is n times the constant; every detail is zero.
  std::vector<double> flat(std::size_t(n) * n, 2.0);
  haarForward(flat.data(), n);
  CHECK(flat[0] == doctest::Approx(2.0 * n));
  for (std::size_t i = 1; i < flat.size(); ++i) CHECK(std::abs(flat[i]) < 1e-12);
}

TEST_CASE("Haar: perfect reconstruction and Parseval on random images of every power-of-two size") {
  for (int n : {1, 2, 4, 32, 128}) {
    std::vector<double> image = randomImage(n, std::uint32_t(n)), original = image;
    double energy = 0, transformed = 0;
    for (double x : image) energy += x * x;
    haarForward(image.data(), n);
    for (double x : image) transformed += x * x;
    CHECK(transformed == doctest::Approx(energy).epsilon(1e-12));
    haarInverse(image.data(), n);
    double worst = 0;
    for (std::size_t i = 0; i < image.size(); ++i)
      worst = std::max(worst, std::abs(image[i] - original[i]));
    CHECK(worst < 1e-12);
  }
  CHECK(supportSide(0, 0, 32) == 32);
  CHECK(supportSide(1, 0, 32) == 32);
  CHECK(supportSide(3, 2, 32) == 16);
  CHECK(supportSide(31, 0, 32) == 2);
}

TEST_CASE("Non-linear approximation: the error is the dropped energy, falling as k grows") {
  const int size = 16;
  const std::vector<glm::vec3> light = randomCube(size, 3, 0.01);
  std::vector<glm::vec3> coefficients = light;
  haarForwardCube(coefficients, size);
  double previous = 1e300;
  for (std::size_t k : {1u, 4u, 16u, 64u, 256u, 1536u}) {
    const SparseVector kept = keepLargest(coefficients, size, k);
    CHECK(kept.size() == std::min<std::size_t>(k, coefficients.size()));
    // Rebuild the cube from the kept terms and measure its error against the light.
    std::vector<glm::vec3> approx(coefficients.size(), glm::vec3(0));
    for (std::size_t i = 0; i < kept.size(); ++i) approx[kept.index[i]] = kept.value[i];
    double droppedEnergy = 0;
    for (std::size_t i = 0; i < coefficients.size(); ++i) {
      const glm::dvec3 d = glm::dvec3(coefficients[i]) - glm::dvec3(approx[i]);
      droppedEnergy += glm::dot(d, d);
    }
    haarInverseCube(approx, size);
    double error = 0;
    for (std::size_t i = 0; i < light.size(); ++i) {
      const glm::dvec3 d = glm::dvec3(light[i]) - glm::dvec3(approx[i]);
      error += glm::dot(d, d);
    }
    CHECK(error == doctest::Approx(droppedEnergy).epsilon(1e-4));
    CHECK(error <= previous);
    previous = error;
  }
  CHECK(previous < 1e-6);  // every coefficient kept: exact
  // Area weighting keeps coarser terms: its kept supports are on average at least as large.
  const SparseVector byMagnitude = keepLargest(coefficients, size, 40, Selection::Magnitude);
  const SparseVector byArea = keepLargest(coefficients, size, 40, Selection::AreaWeighted);
  auto meanSupport = [&](const SparseVector& v) {
    double sum = 0;
    for (std::uint32_t i : v.index) {
      const std::uint32_t inFace = i % std::uint32_t(size * size);
      sum += supportSide(int(inFace / size), int(inFace % size), size);
    }
    return sum / double(v.size());
  };
  CHECK(meanSupport(byArea) >= meanSupport(byMagnitude));
}

TEST_CASE("16-bit quantisation: every coefficient and every dot product within the stated bound") {
  const int size = 8;
  std::vector<glm::vec3> transport = randomCube(size, 5, 0.05), light = randomCube(size, 6, 0.02);
  haarForwardCube(transport, size);
  haarForwardCube(light, size);
  const SparseVector kept = keepLargest(transport, size, 100);
  const QuantizedVector q = quantize(kept);
  REQUIRE(std::equal(q.index.begin(), q.index.end(), kept.index.begin(), kept.index.end()));
  CHECK(q.bytes() == 100 * 8);  // 16-bit index and three 16-bit values
  glm::dvec3 lightMass(0);
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const glm::dvec3 error = glm::abs(q.value(i) - glm::dvec3(kept.value[i]));
    for (int c = 0; c < 3; ++c) CHECK(error[c] <= q.bound()[c] * (1 + 1e-6));
    lightMass += glm::abs(glm::dvec3(light[kept.index[i]]));
  }
  const glm::dvec3 exact = dot(kept, light), quantized = dot(q, LightChannels(light));
  for (int c = 0; c < 3; ++c) {
    CHECK(std::abs(quantized[c] - exact[c]) <= q.bound()[c] * lightMass[c] * (1 + 1e-6));
    CHECK(std::abs(quantized[c] - exact[c]) > 0);  // it does round
  }
  // An all-zero vector: nothing kept, nothing divided by zero.
  const SparseVector none = keepLargest(std::vector<glm::vec3>(6 * 4 * 4, glm::vec3(0)), 4, 10);
  CHECK(none.size() == 0);
  CHECK(quantize(none).bytes() == 0);
}
