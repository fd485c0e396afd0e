// Benchmark: a PRT frame's sparse dot products (prt/sparse_vector.hpp), the vectorised gather over
// split light channels (the clone the CPU selects) against the scalar loop over RGB triples that
// preceded it, measured in the same run on the same vectors, with how far apart their results
// are, and the achieved bandwidth against this machine's STREAM triad (roofline.hpp).
//   build/bench/prt_dot_bench [VERTICES] [TERMS] [CUBE]   (default 37228 768 16: the default
//   object)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include <lucent/prt/sparse_vector.hpp>
#include <lucent/util/rng.hpp>

#include "roofline.hpp"

using namespace lucent;

namespace {
/// The scalar loop the vectorised one replaced: each term's RGB triple, in double.
glm::dvec3 scalarDot(const prt::QuantizedVector& a, const std::vector<glm::vec3>& light) {
  glm::dvec3 sum(0);
  for (std::size_t i = 0; i < a.index.size(); ++i)
    sum += a.value(i) * glm::dvec3(light[a.index[i]]);
  return sum;
}

/// `count` vectors of `terms` random indices into `texels` with random values.
std::vector<prt::QuantizedVector> randomVectors(std::size_t count, std::size_t terms,
                                                std::size_t texels) {
  util::Rng rng(7);
  std::vector<prt::QuantizedVector> out(count);
  for (auto& v : out) {
    prt::SparseVector s;
    for (std::size_t i = 0; i < terms; ++i) {
      s.index.push_back(std::uint32_t(rng.uniform() * double(texels)) % std::uint32_t(texels));
      s.value.push_back(glm::vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5));
    }
    v = prt::quantize(s);
  }
  return out;
}

template <class Dot>
double secondsPerFrame(const std::vector<prt::QuantizedVector>& vectors, const Dot& dot,
                       glm::dvec3& checksum) {
  double best = 1e30;
  for (int run = 0; run < 5; ++run) {
    const auto start = std::chrono::steady_clock::now();
    glm::dvec3 sum(0);
    for (const auto& v : vectors) sum += dot(v);
    best = std::min(
        best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    checksum = sum;
  }
  return best;
}
}  // namespace

int main(int argc, char** argv) {
  const std::size_t vertices = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 37228;
  const std::size_t terms = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 768;
  const std::size_t cube = argc > 3 ? std::strtoul(argv[3], nullptr, 10) : 16;
  if (vertices == 0 || terms == 0 || cube == 0 || cube > 64 || vertices > 10000000 ||
      terms > 6 * cube * cube) {
    std::fprintf(stderr, "usage: prt_dot_bench [VERTICES] [TERMS <= 6 CUBE^2] [CUBE <= 64]\n");
    return 2;
  }
  const std::size_t texels = 6 * cube * cube;
  const auto vectors = randomVectors(vertices, terms, texels);
  util::Rng rng(11);
  std::vector<glm::vec3> light(texels);
  for (auto& l : light) l = glm::vec3(rng.uniform(), rng.uniform(), rng.uniform());
  const prt::LightChannels channels(light);

  glm::dvec3 scalarSum, vectorSum;
  const double scalar = secondsPerFrame(
      vectors, [&](const auto& v) { return scalarDot(v, light); }, scalarSum);
  const double vectorised = secondsPerFrame(
      vectors, [&](const auto& v) { return prt::dot(v, channels); }, vectorSum);
  // Bytes a frame reads: each term's index and three 16-bit values, and three light floats.
  const double bytes =
      double(vertices) * double(terms) * double(sizeof(prt::QuantizedVector::Index) + 6 + 12);
  const double triad = bench::triadGigabytesPerSecond(1);
  std::printf("%zu vertices x %zu terms over %zu texels, one thread:\n", vertices, terms, texels);
  std::printf("  scalar RGB loop (baseline)   %8.2f ms a frame\n", 1e3 * scalar);
  std::printf("  vectorised channels          %8.2f ms a frame   %.2fx\n", 1e3 * vectorised,
              scalar / vectorised);
  std::printf("  results differ by            %8.1e relative\n",
              glm::length(vectorSum - scalarSum) / glm::length(scalarSum));
  std::printf("  bandwidth %.1f GB/s, %.0f %% of this machine's STREAM triad (%.1f GB/s)\n",
              bytes / vectorised / 1e9, 100 * bytes / vectorised / 1e9 / triad, triad);
  return 0;
}
