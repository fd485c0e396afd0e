// The single-scattering term (reference/single_scattering.hpp) against the path tracer counting
// single scattering alone (orders=single), which shares none of its code: index-matched under a
// point light and an environment, where the term's only approximation is its depth quadrature, and
// behind a Fresnel boundary, where it leaves out internally reflected paths and bends the light's
// path by Jensen 2001's flat-boundary estimate.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include <lucent/reference/single_scattering.hpp>
#include <lucent/scene/shapes.hpp>

#include "path_trace_estimate.hpp"
#include "raycast/embree_ray_caster.hpp"

using namespace lucent;
using namespace lucent::test;

namespace {
constexpr double kRadius = 1.0;  // mm
constexpr std::uint64_t kSeed = 17;

struct Comparison {
  Estimate traced;
  glm::dvec3 term{0};
};

/// How the term's mean over the rays is taken: over the path tracer's own rays, or, where the light
/// is the same from every direction (a uniform environment) and the radiance depends only on how
/// far from the centre a ray passes, over rays at equal-area impact parameters.
enum class TermRays { Same, Rings };

/// Both estimators over rays through a sphere of `medium`, lit by `lights`.
Comparison compare(const reference::Medium& medium, const std::vector<scene::Light>& lights,
                   std::size_t rays, TermRays termRays,
                   reference::SingleScatteringSettings::Path path =
                       reference::SingleScatteringSettings::Path::Refracted) {
  reference::MediumScene media;
  media.addBody(scene::shapes::sphere(kRadius, 5), media.addMedium(medium), 0);
  const raycast::EmbreeRayCaster caster(media.mesh);
  reference::PathTracerSettings s;
  s.rayEpsilon = 1e-6;
  s.orders = reference::ScatteringOrders::Single;
  const reference::VolumePathTracer tracer(media, caster, lights, s);
  // Rays that hit: through a disc a little inside the tessellated sphere's silhouette.
  const double disc = 0.9 * kRadius;
  auto rayOf = [disc](std::size_t, util::Rng& rng) { return rayThroughSphere(disc, rng); };
  Comparison out;
  out.traced = estimate(tracer, rays, rayOf, kSeed);

  reference::HomogeneousScattering h;
  h.sigmaS = medium.sigmaS, h.sigmaT = medium.sigmaA + medium.sigmaS, h.g = medium.g;
  h.eta = medium.eta;
  reference::SingleScatteringSettings settings;
  settings.path = path;
  settings.rayEpsilon = 1e-6;
  settings.environmentStrata = termRays == TermRays::Same ? 6 : 16;
  const std::vector<glm::vec3> normals = media.mesh.vertexNormals();
  const reference::SingleScattering term(h, lights, media.mesh, normals, caster, settings);
  auto termAlong = [&](const scene::Ray& r) {
    const auto hit = caster.intersect(r.origin, r.direction, 0, 1e30);
    REQUIRE(hit);
    const glm::dvec3 x = r.origin + r.direction * hit->t;
    const glm::dvec3 face = glm::normalize(media.mesh.areaVector(hit->triangle));
    const glm::dvec3 n = scene::shadingNormal(media.mesh, normals, hit->triangle,
                                              {1 - hit->u - hit->v, hit->u, hit->v});
    return term.radiance(x, n, face, -r.direction);
  };
  const std::size_t count = termRays == TermRays::Same ? rays : 96;
  std::vector<glm::dvec3> values(count);
  util::tbbFor(count, [&](std::size_t i0, std::size_t i1) {
    for (std::size_t i = i0; i < i1; ++i) {
      if (termRays == TermRays::Same) {
        util::Rng rng(kSeed * 7919 + i);  // the ray estimate() traced
        values[i] = termAlong(rayOf(i, rng));
      } else {  // ring i of equal area, crossed at an oblique azimuth (no mesh symmetry plane)
        const double b = disc * std::sqrt((i + 0.5) / double(count));
        const glm::dvec3 side = glm::normalize(glm::dvec3(0.8, 0.6, 0.0));
        values[i] = termAlong({side * b + glm::dvec3(0, 0, -4 * kRadius), {0, 0, 1}});
      }
    }
  });
  for (const auto& v : values) out.term += v;
  out.term /= double(count);
  return out;
}

/// The relative difference per channel, with the path tracer's standard error beside it.
void report(const std::string& what, const Comparison& c) {
  for (int ch = 0; ch < 3; ++ch)
    MESSAGE(what << " channel " << ch << ": path tracer " << c.traced.mean[ch] << " +- "
                 << c.traced.stdError[ch] << ", term " << c.term[ch] << " (ratio "
                 << c.term[ch] / c.traced.mean[ch] << ")");
}

/// Agreement within `sigmas` standard errors plus a relative `bias` allowance.
void checkAgrees(const Comparison& c, double sigmas, double bias) {
  for (int ch = 0; ch < 3; ++ch) {
    REQUIRE(c.traced.mean[ch] > 0);
    CHECK(std::isfinite(c.term[ch]));
    CHECK(std::abs(c.term[ch] - c.traced.mean[ch]) <=
          sigmas * c.traced.stdError[ch] + bias * c.traced.mean[ch]);
  }
}
}  // namespace

TEST_CASE("Single scattering, index-matched: the term equals the path tracer's orders=single") {
  // Channels from thin to thick (optical radius 0.6, 2.5, 6), forward and backward scattering.
  const reference::Medium m = medium({0.1, 0.5, 2.0}, {0.5, 2.0, 4.0}, 1.0, 0.5);
  SUBCASE("a point light to the side") {
    const std::vector<scene::Light> lights{scene::PointLight{{6, 4, -3}, glm::dvec3(60)}};
    const Comparison c = compare(m, lights, 40000, TermRays::Same);
    report("matched, point light", c);
    checkAgrees(c, 4, 0.01);
    checkClean(c.traced.stats);
  }
  SUBCASE("a uniform environment, g = -0.3") {
    const reference::Medium back = medium({0.1, 0.5, 2.0}, {0.5, 2.0, 4.0}, 1.0, -0.3);
    const Comparison c = compare(back, {uniformEnvironment(1.0)}, 40000, TermRays::Rings);
    report("matched, environment", c);
    checkAgrees(c, 4, 0.02);
  }
}

TEST_CASE(
    "Single scattering behind a Fresnel boundary (eta 1.3) under an environment equals the path "
    "tracer's") {
  // The view path's and the light's reflections inside carry much of it: left out, the thin
  // channel falls 37 % short of the path tracer.
  const reference::Medium m = medium({0.1, 0.5, 2.0}, {0.5, 2.0, 4.0}, 1.3, 0.5);
  const Comparison c = compare(m, {uniformEnvironment(1.0)}, 40000, TermRays::Rings);
  report("eta 1.3, environment", c);
  checkAgrees(c, 4, 0.02);
  // Wang et al. 2005's negative-normal path, measured (its error is the approximation's, stated in
  // docs/accuracy/prt.md): finite, positive, and within a factor 1.5 here.
  const Comparison normal = compare(m, {uniformEnvironment(1.0)}, 4000, TermRays::Rings,
                                    reference::SingleScatteringSettings::Path::NegativeNormal);
  report("eta 1.3, environment, negative-normal path", normal);
  for (int ch = 0; ch < 3; ++ch) {
    CHECK(normal.term[ch] > c.traced.mean[ch] / 1.5);
    CHECK(normal.term[ch] < c.traced.mean[ch] * 1.5);
  }
}
