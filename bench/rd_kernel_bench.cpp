// Benchmark: cost of one Rd evaluation in the brute-force truth's inner loop, the vectorised float kernel
// (with whatever clone the CPU selects) against the scalar double path with std::exp, measured in the
// same run, and how far apart their sums are.
//   build/bench/rd_kernel_bench
#include <chrono>
#include <cstdio>

#include <lucent/optics/materials.hpp>
#include <lucent/reference/dipole_truth.hpp>
#include <lucent/scene/shapes.hpp>

using namespace lucent;

namespace {
struct NothingOccludes final : scene::RayCaster {
  std::optional<scene::RayHit> intersect(const glm::dvec3&, const glm::dvec3&, double, double) const override { return {}; }
  bool occluded(const glm::dvec3&, const glm::dvec3&, double, double) const override { return false; }
};

template <class T>
std::pair<double, glm::dvec3> nsPerEvaluation(const reference::SurfaceSamples& samples, int points) {
  const optics::Material m = *optics::findMaterial("skin1");
  const auto d = optics::Dipole<T>::make(optics::Rgb<T>(m.sigmaA), optics::Rgb<T>(m.sigmaSPrime), T(m.eta));
  const NothingOccludes caster;
  const std::vector<scene::Light> light{scene::DirectionalLight{glm::dvec3(0, 0, 1), glm::dvec3(1)}};
  const reference::DipoleTruth<T> truth(samples, d, light, caster, scene::IrradianceSettings{});
  const auto start = std::chrono::steady_clock::now();
  glm::dvec3 sum(0);
  for (int k = 0; k < points; ++k) sum += truth.radiosity(glm::dvec3(0.01 * k, 0.02 * k, 0.5));
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {s / points / double(truth.stats().litSamples) * 1e9, sum};
}
}  // namespace

int main() {
  scene::TriangleMesh slab = scene::shapes::slab(0.1, 0.05);
  slab.scaleToSize(20);
  const auto samples = reference::buildSurfaceSamples(slab, 0.1);
  std::printf("%zu samples, 200 shading points, one thread\n", samples.size());
  const auto [nsFloat, sumFloat] = nsPerEvaluation<float>(samples, 200);
  const auto [nsDouble, sumDouble] = nsPerEvaluation<double>(samples, 200);
  std::printf("float kernel : %6.2f ns per Rd evaluation\n", nsFloat);
  std::printf("double scalar: %6.2f ns per Rd evaluation\n", nsDouble);
  std::printf("speed-up     : %6.1fx; sums differ by %.2e relative (red)\n", nsDouble / nsFloat,
              std::abs(sumFloat.x / sumDouble.x - 1));
  return 0;
}
