#pragma once
// Shared by the path-tracer tests: the mean and standard error of path-traced estimates along
// random rays, rays through a sphere, a uniform environment, a test medium, the agreement of two
// estimates, and the clean-run checks.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <string>

#include <lucent/reference/volume_path_tracer.hpp>
#include <lucent/util/basis.hpp>

#include "util/tbb_parallel.hpp"

namespace lucent::test {
using namespace lucent;

struct Estimate {
  glm::dvec3 mean{0}, stdError{0};
  reference::PathTracerStats stats;
};

/// Mean of `n` path-traced estimates along the rays `rayOf(i)` (each its own seeded generator).
inline Estimate estimate(const reference::VolumePathTracer& tracer, std::size_t n,
                         const std::function<scene::Ray(std::size_t, util::Rng&)>& rayOf,
                         std::uint64_t seed) {
  constexpr std::size_t kBlocks = 64;
  std::vector<glm::dvec3> sum(kBlocks, glm::dvec3(0)), sumSq(kBlocks, glm::dvec3(0));
  std::vector<reference::PathTracerStats> stats(kBlocks);
  util::tbbFor(kBlocks, [&](std::size_t b0, std::size_t b1) {
    for (std::size_t b = b0; b < b1; ++b)
      for (std::size_t i = b; i < n; i += kBlocks) {
        util::Rng rng(seed * 7919 + i);
        const scene::Ray r = rayOf(i, rng);
        const glm::dvec3 l = tracer.sample(r.origin, r.direction, rng, stats[b]);
        sum[b] += l, sumSq[b] += l * l;
      }
  });
  Estimate e;
  glm::dvec3 s(0), s2(0);
  for (std::size_t b = 0; b < kBlocks; ++b) s += sum[b], s2 += sumSq[b], e.stats.add(stats[b]);
  e.mean = s / double(n);
  e.stdError = glm::sqrt(glm::max(glm::dvec3(0), s2 / double(n) - e.mean * e.mean) / double(n - 1));
  return e;
}

/// Rays from far away at random through the disc that covers a sphere of `radius` at the origin.
inline scene::Ray rayThroughSphere(double radius, util::Rng& rng) {
  const double z = 1 - 2 * rng.uniform(), phi = 2 * optics::kPi * rng.uniform();
  const glm::dvec3 dir(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi),
                       z);
  glm::dvec3 t, b;
  util::orthonormalBasis(dir, t, b);
  const double r = radius * std::sqrt(rng.uniform()), a = 2 * optics::kPi * rng.uniform();
  const glm::dvec3 origin = -4 * radius * dir + r * (std::cos(a) * t + std::sin(a) * b);
  return {origin, dir};
}

inline scene::EnvironmentLight uniformEnvironment(double radiance) {
  scene::EnvironmentLight env;
  env.width = env.height = 1;
  env.radiance = {glm::vec3(float(radiance))};
  return env;
}

inline reference::Medium medium(glm::dvec3 sigmaA, glm::dvec3 sigmaS, double eta, double g = 0) {
  reference::Medium m;
  m.name = "test";
  m.sigmaA = sigmaA, m.sigmaS = sigmaS, m.eta = eta, m.g = g;
  return m;
}

/// Two independent estimates of the same value agree per channel within 4 combined standard
/// errors, and that error is below `resolution` of a's mean: the test could tell a difference of
/// about 4 x resolution. `what` names a and b in the message.
inline void checkAgree(const Estimate& a, const Estimate& b, double resolution,
                       const std::string& what) {
  for (int c = 0; c < 3; ++c) {
    const double se = std::hypot(a.stdError[c], b.stdError[c]);
    INFO(what << ", channel " << c << ": " << a.mean[c] << " +- " << a.stdError[c] << " against "
              << b.mean[c] << " +- " << b.stdError[c]);
    CHECK(std::abs(a.mean[c] - b.mean[c]) <= 4 * se);
    CHECK(se < resolution * a.mean[c]);
  }
}

inline void checkClean(const reference::PathTracerStats& s) {
  CHECK(s.nonFiniteSamples == 0);
  CHECK(s.mediumMismatches == 0);
  CHECK(s.truncatedPaths == 0);
  CHECK(s.medium.majorantViolations == 0);
  CHECK(double(s.leakedPaths) <= 1e-4 * double(s.cameraSamples));
}

}  // namespace lucent::test
