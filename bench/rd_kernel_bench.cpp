// Benchmark: cost of one Rd evaluation in the brute-force truth's inner loop, the vectorised float
// kernel (with whatever clone the CPU selects) against the scalar double path with std::exp,
// measured in the same run, and how far apart their sums are; the float kernel's flop rate against
// this machine's FMA peak, measured in the same process (roofline.hpp). Then the radial-table sum
// of tsis, the hybrid and tsm: per-channel gathers against one node record a term (AVX-512), in
// the same run.
//   build/bench/rd_kernel_bench
#include <chrono>
#include <cstdio>
#include <thread>

#include "roofline.hpp"

#include <algorithm>

#include <lucent/optics/materials.hpp>
#include <lucent/reference/dipole_truth.hpp>
#include <lucent/reference/radial_table_sum.hpp>
#include <lucent/scene/shapes.hpp>

using namespace lucent;

namespace {
struct NothingOccludes final : scene::RayCaster {
  std::optional<scene::RayHit> intersect(const glm::dvec3&, const glm::dvec3&, double,
                                         double) const override {
    return {};
  }
  bool occluded(const glm::dvec3&, const glm::dvec3&, double, double) const override {
    return false;
  }
};

/// Float operations of one evaluation of the classic dipole's kernel (reference/rd_sum_kernel.hpp,
/// counted from the source; an FMA is 2, sqrt and division 1 each although their throughput is a
/// fraction of an FMA's):
///   per sample: the offset and r^2, 3 + 5 = 8;
///   per channel (x3): 2 x (r^2 + z^2, sqrt, -sigma_tr d) = 6; 2 x exp (fast_exp.hpp: 3 for n,
///   4 for r, 1 for r^2, 13 for the polynomial, 1 for the scale) = 44; 2 x the pole's term
///   (1 + sigma_tr d as an FMA, times z, times e, d^3, the division) = 14; their sum and the
///   constant, 2; w Rd into the sum, 2: together 68.
constexpr double kFlopsPerEvaluation = 8 + 3 * 68;
/// Of those, the square roots and divisions (6 each), which the FMA peak does not bound.
constexpr double kSqrtAndDivPerEvaluation = 12;

/// Float operations of one term of the radial-table sum (radial_table_sum.hpp), counted from the
/// source as above: offset and r^2 8; u = sqrt(sqrt(r^2)) scale 3; the node and its fraction 4;
/// per channel (x3) the lerp as an FMA 2, the range mask 1, times w 1, into the sum 1: 30.
constexpr double kFlopsPerTableTerm = 30;

/// ns per term of the radial-table sum over `samples` (the truth's samples, weights 1) at `points`
/// shading points, by `sum`; and the total, to compare paths.
template <class Sum>
std::pair<double, double> nsPerTableTerm(const reference::SurfaceSamples& samples, int points,
                                         const reference::PlanarRadialTable& table, Sum sum) {
  std::vector<float> x, y, z, w(samples.size(), 1.0f);
  for (const auto& p : samples.position)
    x.push_back(float(p.x)), y.push_back(float(p.y)), z.push_back(float(p.z));
  const reference::RdKernelSamples s{x.data(), y.data(), z.data(), w.data(),
                                     w.data(), w.data(), x.size()};
  double total = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < points; ++k) {
    double out[3] = {0, 0, 0};
    sum(s, table, float(0.01 * k), float(0.02 * k), 0.5f, out);
    total += out[0] + out[1] + out[2];
  }
  const double sec =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {sec / points / double(s.n) * 1e9, total};
}

void tableSumFigures(const reference::SurfaceSamples& samples, double peak1) {
  const optics::Material m = *optics::findMaterial("skin1");
  const auto d = optics::Dipole<float>::make(optics::Rgb<float>(m.sigmaA),
                                             optics::Rgb<float>(m.sigmaSPrime), float(m.eta));
  const reference::PlanarRadialTable table(optics::RdTable<float>(d, 30.0f));
  const int points = 2000;
  const auto gathered = nsPerTableTerm(
      samples, points, table, [](auto& s, auto& t, float x, float y, float z, double* out) {
        reference::radialTableSumGathered(s, t, x, y, z, 0, s.n, out);
      });
  const auto best = nsPerTableTerm(samples, points, table, reference::radialTableSum);
  std::printf("table sum    : %zu nodes, %d shading points, one thread\n", table.size(), points);
  std::printf("  gathers    : %6.2f ns a term, %.1f GFLOP/s (%.0f %% of the FMA peak)\n",
              gathered.first, kFlopsPerTableTerm / gathered.first,
              100 * kFlopsPerTableTerm / gathered.first / peak1);
  std::printf(
      "  this CPU's : %6.2f ns a term, %.1f GFLOP/s (%.0f %% of the FMA peak), %.2fx; "
      "totals differ by %.1e relative (%s)\n",
      best.first, kFlopsPerTableTerm / best.first, 100 * kFlopsPerTableTerm / best.first / peak1,
      gathered.first / best.first, std::abs(best.second / gathered.second - 1),
#if LUCENT_HAS_AVX512_TABLE_SUM
      reference::cpuHasAvx512() ? "AVX-512 node records" : "the same gathers"
#else
      "the same gathers"
#endif
  );
}

template <class T>
std::pair<double, glm::dvec3> nsPerEvaluation(const reference::SurfaceSamples& samples,
                                              int points) {
  const optics::Material m = *optics::findMaterial("skin1");
  const auto d =
      optics::Dipole<T>::make(optics::Rgb<T>(m.sigmaA), optics::Rgb<T>(m.sigmaSPrime), T(m.eta));
  const NothingOccludes caster;
  const std::vector<scene::Light> light{
      scene::DirectionalLight{glm::dvec3(0, 0, 1), glm::dvec3(1)}};
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
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const double peak1 = bench::fmaPeakGflops(1), peakAll = bench::fmaPeakGflops(cores);
  std::printf(
      "roofline     : FMA peak %.1f GFLOP/s on 1 thread, %.1f on %u; STREAM triad %.1f GB/s "
      "on 1 thread, %.1f on %u\n",
      peak1, peakAll, cores, bench::triadGigabytesPerSecond(1),
      bench::triadGigabytesPerSecond(cores), cores);
  const double achieved = kFlopsPerEvaluation / nsFloat;  // flops per ns = GFLOP/s
  std::printf(
      "float kernel : %.0f flops per evaluation (%.0f of them sqrt or division): %.1f GFLOP/s, "
      "%.0f %% of the 1-thread FMA peak\n",
      kFlopsPerEvaluation, kSqrtAndDivPerEvaluation, achieved, 100 * achieved / peak1);
  tableSumFigures(samples, peak1);
  return 0;
}
