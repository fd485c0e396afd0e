// Manifold next-event estimation (reference/manifold_next_event.hpp): the refraction through one
// facet against Fermat's principle and a traced ray tube, the facet walk against a search of every
// facet, and the path tracer's single scattering under delta lights behind eta 1.3 against a closed
// form and an integral written here.
#include <doctest/doctest.h>

#include <cmath>
#include <set>
#include <string>

#include <lucent/optics/fresnel.hpp>
#include <lucent/optics/phase_hg.hpp>
#include <lucent/reference/manifold_next_event.hpp>
#include <lucent/scene/facet_adjacency.hpp>
#include <lucent/scene/shapes.hpp>

#include "path_trace_estimate.hpp"
#include "raycast/embree_ray_caster.hpp"

using namespace lucent;
using namespace lucent::test;

namespace {

/// A plane through q0 with unit normal n facing the light; indices nIn below, nOut above.
struct Plane {
  glm::dvec3 q0, n;
  double nIn, nOut;
};

/// The point of the plane minimising the optical path nIn |y - x| + nOut |p - y| (Fermat), by
/// damped Newton on the path's gradient and Hessian in plane coordinates: no Snell's law in it.
glm::dvec3 fermatPoint(const Plane& pl, const glm::dvec3& x, const glm::dvec3& p) {
  glm::dvec3 e1, e2;
  util::orthonormalBasis(pl.n, e1, e2);
  auto at = [&](double a, double b) { return pl.q0 + a * e1 + b * e2; };
  auto path = [&](const glm::dvec3& y) {
    return pl.nIn * glm::length(y - x) + pl.nOut * glm::length(p - y);
  };
  double a = 0, b = 0;
  for (int i = 0; i < 200; ++i) {
    const glm::dvec3 y = at(a, b), u = y - x, v = y - p;
    const double lu = glm::length(u), lv = glm::length(v);
    const glm::dvec3 grad = pl.nIn * u / lu + pl.nOut * v / lv;
    // Hessian of |y - q| is (I - w w^T) / |y - q| with w the unit difference.
    auto hess = [&](const glm::dvec3& s, const glm::dvec3& t) {
      return pl.nIn * (glm::dot(s, t) - glm::dot(s, u) * glm::dot(t, u) / (lu * lu)) / lu +
             pl.nOut * (glm::dot(s, t) - glm::dot(s, v) * glm::dot(t, v) / (lv * lv)) / lv;
    };
    const double g1 = glm::dot(grad, e1), g2 = glm::dot(grad, e2);
    const double h11 = hess(e1, e1), h12 = hess(e1, e2), h22 = hess(e2, e2);
    const double det = h11 * h22 - h12 * h12;
    double da = -(h22 * g1 - h12 * g2) / det, db = -(h11 * g2 - h12 * g1) / det;
    double step = 1;
    while (step > 1e-12 && !(path(at(a + step * da, b + step * db)) <= path(y))) step *= 0.5;
    a += step * da, b += step * db;
    if (std::hypot(step * da, step * db) < 1e-15 * (lu + lv)) break;
  }
  return at(a, b);
}

/// Where a ray from `origin` along unit `d` (from above) refracts into the plane's lower side and
/// then meets the plane through x perpendicular to `axis`.
glm::dvec3 throughPlane(const Plane& pl, const glm::dvec3& origin, const glm::dvec3& d,
                        const glm::dvec3& x, const glm::dvec3& axis) {
  const double t = glm::dot(pl.q0 - origin, pl.n) / glm::dot(d, pl.n);
  const glm::dvec3 y = origin + t * d;
  const double ratio = pl.nOut / pl.nIn, cosI = -glm::dot(d, pl.n);
  const double cosT = std::sqrt(1 - ratio * ratio * (1 - cosI * cosI));
  const glm::dvec3 refracted = ratio * d + (ratio * cosI - cosT) * pl.n;
  return y + (glm::dot(x - y, axis) / glm::dot(refracted, axis)) * refracted;
}

/// The irradiance perpendicular to the ray at x per unit light power, from a ray tube traced
/// through the plane: central differences of where neighbouring rays land.
double tubeIrradiance(const Plane& pl, const glm::dvec3& x, const glm::dvec3& y,
                      const glm::dvec3* pointLight, const glm::dvec3& towardsLight) {
  const glm::dvec3 axis = glm::normalize(x - y);
  const glm::dvec3 d0 = pointLight ? glm::normalize(y - *pointLight) : -towardsLight;
  glm::dvec3 e1, e2;
  util::orthonormalBasis(d0, e1, e2);
  const double h = 1e-5 * glm::length(x - y);
  glm::dvec3 landed[2], spread[2];
  for (int k = 0; k < 2; ++k) {
    const glm::dvec3 e = k ? e2 : e1;
    glm::dvec3 plus, minus;
    if (pointLight) {  // rays in directions d0 +- h e / distance: a solid angle
      const double dist = glm::length(y - *pointLight);
      const glm::dvec3 dp = glm::normalize(d0 + (h / dist) * e),
                       dm = glm::normalize(d0 - (h / dist) * e);
      plus = throughPlane(pl, *pointLight, dp, x, axis);
      minus = throughPlane(pl, *pointLight, dm, x, axis);
      spread[k] = (dp - dm) / (2 * h);
    } else {  // parallel rays offset by +- h e: an area across the beam
      const glm::dvec3 start = y - 10.0 * d0;
      plus = throughPlane(pl, start + h * e, d0, x, axis);
      minus = throughPlane(pl, start - h * e, d0, x, axis);
      spread[k] = e / 1.0;
    }
    landed[k] = (plus - minus) / (2 * h);
  }
  const double cosOut = -glm::dot(d0, pl.n);
  const double ft = optics::fresnelTransmittance(cosOut, pl.nIn / pl.nOut);
  return ft * glm::length(glm::cross(spread[0], spread[1])) /
         glm::length(glm::cross(landed[0], landed[1]));
}

reference::MediumScene oneTriangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                                   double nIn, double nOut) {
  reference::MediumScene s;
  const auto inner = s.addMedium(medium(glm::dvec3(0.1), glm::dvec3(1), nIn));
  const auto outer = s.addMedium(medium(glm::dvec3(0), glm::dvec3(0), nOut));
  s.mesh.positions = {glm::vec3(a), glm::vec3(b), glm::vec3(c)};
  s.mesh.triangles = {glm::uvec3(0, 1, 2)};
  s.inside = {inner};
  s.outside = {outer};
  return s;
}

reference::LightEmitter pointEmitter(const glm::dvec3& p) {
  reference::LightEmitter e;
  e.kind = reference::LightEmitter::Kind::Point;
  e.position = p;
  return e;
}
reference::LightEmitter directionalEmitter(const glm::dvec3& towards) {
  reference::LightEmitter e;
  e.kind = reference::LightEmitter::Kind::Directional;
  e.towards = glm::normalize(towards);
  return e;
}

}  // namespace

TEST_CASE(
    "A refraction through one facet is Fermat's point, and its irradiance is a traced ray "
    "tube's") {
  // A tilted triangle, large enough that every solution lies on it; x behind it (the inside).
  const glm::dvec3 a(-40, -30, 2), b(40, -30, -3), c(0, 50, 4);
  const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
  for (auto entry : {std::pair{1.3, 1.0}, std::pair{2.4, 1.0}, std::pair{1.0, 1.33}}) {
    const auto nIn = std::get<0>(entry);  // no structured binding: clang 14 cannot capture one
    const auto nOut = std::get<1>(entry);
    const reference::MediumScene scene = oneTriangle(a, b, c, nIn, nOut);
    const Plane plane{a, n, nIn, nOut};
    const glm::dvec3 centre = (a + b + c) / 3.0;
    glm::dvec3 e1, e2;
    util::orthonormalBasis(n, e1, e2);
    util::Rng rng(7);
    for (int trial = 0; trial < 20; ++trial) {
      const glm::dvec3 x = centre + (6 * rng.uniform() - 3) * e1 + (6 * rng.uniform() - 3) * e2 -
                           (0.05 + 5 * rng.uniform()) * n;
      const glm::dvec3 p = centre + (8 * rng.uniform() - 4) * e1 + (8 * rng.uniform() - 4) * e2 +
                           (0.5 + 6 * rng.uniform()) * n;
      INFO("nIn " << nIn << " nOut " << nOut << " trial " << trial);
      const auto point = reference::refractThroughFacet(scene, 0, x, pointEmitter(p));
      REQUIRE(point);
      CHECK(point->onFacet());
      const glm::dvec3 y = fermatPoint(plane, x, p);
      CHECK(glm::length(point->point - y) <= 1e-8 * glm::length(x - p));
      CHECK(point->irradiancePerPower ==
            doctest::Approx(tubeIrradiance(plane, x, y, &p, {})).epsilon(1e-4));
      // Directional: the light along the point's direction, so it also refracts (nOut > nIn).
      const glm::dvec3 towards = glm::normalize(p - y);
      const auto beam = reference::refractThroughFacet(scene, 0, x, directionalEmitter(towards));
      REQUIRE(beam);
      CHECK(glm::length(beam->point - y) <= 1e-8 * glm::length(x - p));
      CHECK(beam->irradiancePerPower ==
            doctest::Approx(tubeIrradiance(plane, x, y, nullptr, towards)).epsilon(1e-4));
      // Snell's law and one plane of incidence.
      const double sinOut = glm::length(glm::cross(beam->towardsLight, n)),
                   sinIn = glm::length(glm::cross(beam->towardsPoint, n));
      CHECK(nOut * sinOut == doctest::Approx(nIn * sinIn).epsilon(1e-9));
      CHECK(std::abs(glm::dot(glm::cross(beam->towardsLight, n), beam->towardsPoint)) < 1e-9);
    }
  }
  SUBCASE("no refraction: the light on x's side, a null interface, light that cannot enter") {
    const reference::MediumScene scene = oneTriangle(a, b, c, 1.3, 1.0);
    const glm::dvec3 x = -2.0 * n;
    CHECK_FALSE(reference::refractThroughFacet(scene, 0, x, pointEmitter(-5.0 * n)));
    CHECK_FALSE(reference::refractThroughFacet(scene, 0, x, directionalEmitter(-n)));
    CHECK_FALSE(reference::refractThroughFacet(oneTriangle(a, b, c, 1.2, 1.2), 0, x,
                                               directionalEmitter(n)));
    // Into a lower index beyond the critical angle no light passes.
    const reference::MediumScene lower = oneTriangle(a, b, c, 1.0, 1.5);
    glm::dvec3 e1, e2;
    util::orthonormalBasis(n, e1, e2);
    CHECK_FALSE(reference::refractThroughFacet(lower, 0, x, directionalEmitter(n + 2.0 * e1)));
    CHECK(reference::refractThroughFacet(lower, 0, x, directionalEmitter(n + 0.5 * e1)));
  }
}

TEST_CASE("Facet adjacency: a closed surface has three neighbours per facet, welded or not") {
  scene::TriangleMesh sphere = scene::shapes::sphere(1.0, 2);
  scene::TriangleMesh soup;  // every triangle its own three vertices
  for (const auto& t : sphere.triangles) {
    const auto base = std::uint32_t(soup.positions.size());
    for (int k = 0; k < 3; ++k) soup.positions.push_back(sphere.positions[t[k]]);
    soup.triangles.push_back(glm::uvec3(base, base + 1, base + 2));
  }
  for (const scene::TriangleMesh* mesh : {&sphere, &soup}) {
    const scene::FacetAdjacency adjacency(*mesh);
    for (std::uint32_t t = 0; t < mesh->triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t n = adjacency.across(t, k);
        REQUIRE(n != scene::FacetAdjacency::kNone);
        CHECK(n != t);
        bool back = false;
        for (int j = 0; j < 3; ++j) back |= adjacency.across(n, j) == t;
        CHECK(back);
      }
  }
  scene::TriangleMesh open = sphere;
  open.triangles.pop_back();
  const scene::FacetAdjacency holed(open);
  int none = 0;
  for (std::uint32_t t = 0; t < open.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) none += holed.across(t, k) == scene::FacetAdjacency::kNone;
  CHECK(none == 3);  // the hole's rim
}

TEST_CASE(
    "The manifold search finds the refraction points that a search of every facet of a convex "
    "body finds, all but a stated share of the light") {
  // On a convex body nothing occludes a refraction point, so solving every facet is the whole
  // truth. A tessellated sphere is a lens: its facets overlap their beams, and near its back the
  // focused light comes through whole bands of facets (a caustic); a second band beyond the gap
  // the search crosses is missed. Measured (-s prints it): 1.2 % of the irradiance at the default
  // gap of 2 facets, 2e-6 at 6, on this stress case (clear, every point of the sphere).
  reference::MediumScene scene;
  scene.addBody(scene::shapes::sphere(1.0, 3),
                scene.addMedium(medium(glm::dvec3(0.1), glm::dvec3(1), 1.3)), 0);
  const raycast::EmbreeRayCaster caster(scene.mesh);
  for (auto entry : {std::pair{2, 0.02}, std::pair{6, 0.003}}) {
    const auto gap = std::get<0>(entry);  // no structured binding: clang 14 cannot capture one
    const auto bound = std::get<1>(entry);
    const reference::ManifoldNextEvent search(scene, caster, gap);
    reference::ManifoldSearchStats stats;
    util::Rng rng(11);
    double all = 0, missed = 0;
    for (int trial = 0; trial < 600; ++trial) {
      const glm::dvec3 dir =
          glm::normalize(glm::dvec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5));
      const glm::dvec3 x = 0.9 * std::cbrt(rng.uniform()) * dir;
      const glm::dvec3 towards =
          glm::normalize(glm::dvec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5));
      const reference::LightEmitter light =
          trial % 2 ? directionalEmitter(towards) : pointEmitter(3.0 * towards);
      std::vector<reference::RefractedConnection> found;
      search.search(x, light, 1e-7, found, stats);
      std::set<std::uint32_t> foundFacets;
      for (const auto& c : found) foundFacets.insert(c.triangle);
      CHECK(foundFacets.size() == found.size());  // each facet once
      std::set<std::uint32_t> truth;
      for (std::uint32_t t = 0; t < scene.mesh.triangles.size(); ++t)
        if (auto c = reference::refractThroughFacet(scene, t, x, light); c && c->onFacet()) {
          truth.insert(t);
          all += c->irradiancePerPower;
          if (!foundFacets.count(t)) missed += c->irradiancePerPower;
        }
      for (std::uint32_t t : foundFacets) CHECK(truth.count(t) == 1);
    }
    INFO("gap " << gap << ": " << stats.solutions << " solutions, " << missed / all
                << " of the irradiance missed, " << stats.multiple << " searches with several");
    CHECK(missed <= bound * all);
    CHECK(stats.multiple > 100);
    CHECK(stats.capped == 0);
  }
}

namespace {

/// A box of 400 x 400 x 200 mean free paths, top face at z = 0: a half-space (leakage ~ e^-100).
reference::MediumScene halfSpace(const reference::Medium& m) {
  reference::MediumScene scene;
  scene.addBody(scene::shapes::box(glm::dvec3(200, 200, 100), 100.0), scene.addMedium(m), 0);
  for (auto& p : scene.mesh.positions) p.z -= 100;
  return scene;
}

/// Unit direction travelling along `d` after refracting from index 1 into `eta` through z = 0.
glm::dvec3 refractDown(const glm::dvec3& d, double eta) {
  const double cosI = -d.z, ratio = 1 / eta;
  const double cosT = std::sqrt(1 - ratio * ratio * (1 - cosI * cosI));
  return ratio * d + (ratio * cosI - cosT) * glm::dvec3(0, 0, 1);
}

}  // namespace

TEST_CASE(
    "Behind eta 1.3, single scattering under a directional light equals the half-space's closed "
    "form") {
  // Light refracted in at theta_i carries E Ft cos(theta_o) / cos(theta_i) across its beam; the
  // view ray refracted to theta_v sees L = Ft_v / eta^2 sigma_s p E_perp / (sigma_t (1 + cos
  // theta_v / cos theta_i)): the integral of e^{-sigma_t s (1 + cos theta_v / cos theta_i)}.
  const double eta = 1.3, albedo = 0.8;
  const glm::dvec3 towardLight(std::sin(1.0), 0, std::cos(1.0));  // 57 degrees
  const std::vector<scene::Light> lights{scene::DirectionalLight{towardLight, glm::dvec3(2.0)}};
  for (double g : {0.0, 0.6}) {
    const reference::MediumScene scene =
        halfSpace(medium(glm::dvec3(1 - albedo), glm::dvec3(albedo), eta, g));
    const raycast::EmbreeRayCaster caster(scene.mesh);
    reference::PathTracerSettings s;
    s.orders = reference::ScatteringOrders::Single;
    s.rayEpsilon = 1e-5 * scene.mesh.bounds().diagonal();  // as a technique sets it
    const reference::VolumePathTracer tracer(scene, caster, lights, s);
    REQUIRE(tracer.manifoldDeltaLights());
    for (double side : {-1.0, 1.0})
      for (double mu : {1.0, 0.6}) {
        const glm::dvec3 toEye(side * std::sqrt(1 - mu * mu), 0, mu);
        const glm::dvec3 lightIn = refractDown(-towardLight, eta),
                         viewIn = refractDown(-toEye, eta);
        const double cosI = -lightIn.z, cosV = -viewIn.z;
        const double ePerp =
            2.0 * optics::fresnelTransmittance(towardLight.z, eta) * towardLight.z / cosI;
        const double exact = optics::fresnelTransmittance(mu, eta) / (eta * eta) * albedo *
                             optics::phaseHG(glm::dot(lightIn, -viewIn), g) * ePerp /
                             (1 + cosV / cosI);
        auto rayOf = [&](std::size_t, util::Rng& rng) {
          const glm::dvec3 target(4 * rng.uniform() - 2, 4 * rng.uniform() - 2, 0);
          return scene::Ray{target + 50.0 * toEye, -toEye};
        };
        const Estimate e = estimate(tracer, 4000, rayOf, 3);
        for (int c = 0; c < 3; ++c) {
          INFO("g " << g << " side " << side << " mu " << mu << ": " << e.mean[c] << " +- "
                    << e.stdError[c] << ", exact " << exact);
          CHECK(std::abs(e.mean[c] - exact) <= 4 * e.stdError[c]);
          CHECK(e.stdError[c] < 0.05 * exact);
        }
        checkClean(e.stats);
        CHECK(e.stats.manifold.capped == 0);
      }
  }
}

TEST_CASE(
    "Behind eta 1.3, single scattering under a point light equals the integral along the view ray "
    "through Fermat's points and traced ray tubes") {
  const double eta = 1.3, albedo = 0.7, g = 0.3;
  const glm::dvec3 light(1.5, 0.5, 2.5), intensity(3.0);
  const reference::MediumScene scene =
      halfSpace(medium(glm::dvec3(1 - albedo), glm::dvec3(albedo), eta, g));
  const raycast::EmbreeRayCaster caster(scene.mesh);
  reference::PathTracerSettings s;
  s.orders = reference::ScatteringOrders::Single;
  s.rayEpsilon = 1e-5 * scene.mesh.bounds().diagonal();
  const reference::VolumePathTracer tracer(scene, caster, {scene::PointLight{light, intensity}}, s);
  const glm::dvec3 toEye = glm::normalize(glm::dvec3(-0.5, 0.2, 1));
  const glm::dvec3 viewIn = refractDown(-toEye, eta);
  // L = Ft_v / eta^2 int_0^inf e^{-s} sigma_s p E_perp(x(s)) e^{-|y - x(s)|} ds, with sigma_t = 1
  // and s = -ln(1 - v): the midpoint rule in v.
  const Plane surface{glm::dvec3(0), glm::dvec3(0, 0, 1), eta, 1.0};
  const int n = 2000;
  double integral = 0;
  for (int i = 0; i < n; ++i) {
    const double v = (i + 0.5) / n, depth = -std::log(1 - v);
    const glm::dvec3 x = depth * viewIn;
    const glm::dvec3 y = fermatPoint(surface, x, light);
    const glm::dvec3 towardsY = glm::normalize(y - x);
    integral += albedo * optics::phaseHG(glm::dot(towardsY, viewIn), g) *
                tubeIrradiance(surface, x, y, &light, {}) * std::exp(-glm::length(y - x)) / n;
  }
  const double exact = optics::fresnelTransmittance(toEye.z, eta) / (eta * eta) * integral * 3.0;
  const Estimate e = estimate(
      tracer, 20000,
      [&](std::size_t, util::Rng&) {
        return scene::Ray{30.0 * toEye, -toEye};
      },
      5);
  for (int c = 0; c < 3; ++c) {
    INFO(e.mean[c] << " +- " << e.stdError[c] << ", integral " << exact);
    CHECK(std::abs(e.mean[c] - exact) <= 4 * e.stdError[c]);
    CHECK(e.stdError[c] < 0.03 * exact);
  }
  checkClean(e.stats);
}

TEST_CASE(
    "Behind eta 1.3 under a point light, manifold next-event estimation and light subpaths agree "
    "on multiple scattering, and single scattering is no longer missing") {
  reference::MediumScene scene;
  scene.addBody(scene::shapes::sphere(1.0, 4),
                scene.addMedium(medium({0.3, 0.1, 0.02}, {2, 3, 5}, 1.3, 0.3)), 0);
  const raycast::EmbreeRayCaster caster(scene.mesh);
  const std::vector<scene::Light> lights{scene::PointLight{{3, 2, 4}, glm::dvec3(20)}};
  reference::PathTracerSettings manifold;
  manifold.orders = reference::ScatteringOrders::Multiple;
  reference::PathTracerSettings joins = manifold;
  joins.deltaLights = reference::DeltaLightStrategy::Joins;
  joins.lightSubpaths = 2;
  auto rayOf = [&](std::size_t, util::Rng& rng) { return rayThroughSphere(1.0, rng); };
  const Estimate a =
      estimate(reference::VolumePathTracer(scene, caster, lights, manifold), 40000, rayOf, 4);
  const Estimate b =
      estimate(reference::VolumePathTracer(scene, caster, lights, joins), 80000, rayOf, 5);
  checkAgree(a, b, 0.06, "manifold against joins");  // a test that could tell a 24 % difference
  for (int c = 0; c < 3; ++c)
    CHECK(a.stdError[c] < b.stdError[c]);  // the point of it, at half the samples
  checkClean(a.stats);
  checkClean(b.stats);
  CHECK(a.stats.manifold.solutions > 0);
  reference::PathTracerSettings single = manifold;
  single.orders = reference::ScatteringOrders::Single;
  const Estimate ss =
      estimate(reference::VolumePathTracer(scene, caster, lights, single), 20000, rayOf, 6);
  for (int c = 0; c < 3; ++c) CHECK(ss.mean[c] > 10 * ss.stdError[c]);
}

TEST_CASE(
    "Behind eta 1.3, manifold next-event estimation from directional lights spread over an "
    "environment cap equals camera paths escaping to that cap, scattering order by order") {
  // The environment-light estimator (paths that escape and happen to hit the cap) shares nothing
  // with the manifold search. The cap's light is split into directional lights at the midpoints of
  // cells of equal solid angle: the quadrature of a smooth response over 22.5 degrees. Unscattered
  // light is left out: a camera ray refracted or reflected straight to the cap sees it, but never
  // a delta light.
  const double alpha = optics::kPi / 8, radiance = 4;
  scene::EnvironmentLight cap;
  cap.width = 8, cap.height = 8;  // the top row of a lat-long map: theta < 22.5 degrees
  cap.radiance.assign(64, glm::vec3(0.0f));
  for (int col = 0; col < 8; ++col) cap.radiance[std::size_t(col)] = glm::vec3(float(radiance));
  const int rings = 2, perRing = 4;
  const double cellSolidAngle = 2 * optics::kPi * (1 - std::cos(alpha)) / (rings * perRing);
  std::vector<scene::DirectionalLight> cells;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < perRing; ++j) {
      const double cosTheta = 1 - (i + 0.5) / rings * (1 - std::cos(alpha));
      const double sinTheta = std::sqrt(1 - cosTheta * cosTheta);
      const double phi = 2 * optics::kPi * (j + 0.5 + 0.5 * i) / perRing;
      const glm::dvec3 towards(sinTheta * std::sin(phi), cosTheta, -sinTheta * std::cos(phi));
      cells.push_back({towards, glm::dvec3(radiance * cellSolidAngle)});
    }
  const std::vector<scene::Light> spread(cells.begin(), cells.end());
  reference::MediumScene scene;
  scene.addBody(scene::shapes::sphere(1.0, 4),
                scene.addMedium(medium({0.3, 0.1, 0.02}, {2, 3, 5}, 1.3, 0.3)), 0);
  const raycast::EmbreeRayCaster caster(scene.mesh);
  auto rayOf = [&](std::size_t, util::Rng& rng) { return rayThroughSphere(1.0, rng); };
  for (const auto orders :
       {reference::ScatteringOrders::Single, reference::ScatteringOrders::Multiple}) {
    reference::PathTracerSettings s;  // escape for the cap, manifold for delta lights
    s.orders = orders;
    const Estimate escaping =
        estimate(reference::VolumePathTracer(scene, caster, {cap}, s), 600000, rayOf, 8);
    const reference::VolumePathTracer manifold(scene, caster, spread, s);
    REQUIRE(manifold.manifoldDeltaLights());
    const Estimate searched = estimate(manifold, 20000, rayOf, 9);
    const std::string order = orders == reference::ScatteringOrders::Single ? "single" : "multiple";
    // A test that could tell a 14 % error.
    checkAgree(searched, escaping, 0.035, order + ": manifold against escaping");
    checkClean(escaping.stats);
    checkClean(searched.stats);
    CHECK(searched.stats.manifold.capped == 0);
  }
}
