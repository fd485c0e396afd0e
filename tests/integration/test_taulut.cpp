// The voxel optical-thickness LUT technique (taulut) end to end, against references computed
// independently of it: closed forms of Eq. 1-3 on slabs, a quadrature of Eq. 1 over the exact
// geometry of a cube with a spherical cavity, and a fresh prepare for material edits.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include <lucent/optics/fresnel.hpp>
#include <lucent/scene/shapes.hpp>
#include <lucent/technique/registry.hpp>

#include "technique/core_registry.hpp"

#include "raycast/embree_ray_caster.hpp"
#include "util/tbb_parallel.hpp"

using namespace lucent;
namespace lt = lucent::technique;

namespace {

optics::Material grey(double sigmaT, double eta = 1.0) {
  optics::Material m;
  m.name = "grey";
  m.sigmaA = optics::Rgb<double>(0.25 * sigmaT);
  m.sigmaSPrime = optics::Rgb<double>(0.75 * sigmaT);
  m.eta = eta;
  return m;
}

/// A scene around `mesh` under a sun of irradiance 1 from `towardLight`.
struct TestScene {
  lt::SceneDescription scene;
  std::unique_ptr<raycast::EmbreeRayCaster> caster;

  TestScene(scene::TriangleMesh mesh, const optics::Material& m, const glm::dvec3& towardLight) {
    scene.meshName = "test mesh";
    scene.mesh = std::move(mesh);
    scene.vertexNormals = scene.mesh.vertexNormals();
    scene.medium.material = m;
    scene.lights = {scene::DirectionalLight{towardLight, glm::dvec3(1)}};
    caster = std::make_unique<raycast::EmbreeRayCaster>(scene.mesh);
    scene.caster = caster.get();
    scene.makeRayCaster = [](const scene::TriangleMesh& mm) {
      return std::make_unique<raycast::EmbreeRayCaster>(mm);
    };
    scene.parallelFor = util::tbbFor;
  }
};

lt::ShadeRequest at(const std::vector<glm::dvec3>& points) {
  lt::ShadeRequest r;
  for (const auto& p : points) {
    reference::ShadingPoint s;
    s.position = p;
    s.cosOut = 1;
    r.points.push_back(s);
  }
  return r;
}

/// B at the points, by taulut with the given knobs.
std::vector<glm::dvec3> radiosity(const TestScene& s, const std::vector<glm::dvec3>& points,
                                  const lt::KnobList& knobs) {
  const auto registry = lt::compiledCoreRegistry();
  const lt::Technique& t = registry.get("taulut");
  return registry.render(t, s.scene, t.values(knobs), at(points)).frame.radiosity;
}

/// Length of segment a -> b inside the cube |x|_inf < h minus its length inside the sphere
/// |x| < r: the exact medium length through the cube with a cavity.
double mediumLength(const glm::dvec3& a, const glm::dvec3& b, double h, double r) {
  const glm::dvec3 d = b - a;
  const double len = glm::length(d);
  double t0 = 0, t1 = 1;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0) continue;
    double e = (-h - a[k]) / d[k], l = (h - a[k]) / d[k];
    if (e > l) std::swap(e, l);
    t0 = std::max(t0, e), t1 = std::min(t1, l);
  }
  const double inCube = t1 > t0 ? (t1 - t0) * len : 0;
  const glm::dvec3 u = d / len;
  const double p = glm::dot(a, u), disc = p * p - (glm::dot(a, a) - r * r);
  if (disc <= 0) return inCube;
  const double s0 = std::clamp(-p - std::sqrt(disc), 0.0, len);
  const double s1 = std::clamp(-p + std::sqrt(disc), 0.0, len);
  return inCube - (s1 - s0);
}

}  // namespace

TEST_CASE(
    "taulut, Eq. 1-3 in closed form: a flat face gives back E, a lit-from-behind slab "
    "E (1 + sigma d) e^{-sigma d}") {
  const double sigma = 1.0, eta = 1.3;
  const double et = optics::fresnelTransmittance(1.0, eta);  // head-on sun of E = 1
  SUBCASE("front-lit: the normalised kernel integrates to one") {
    TestScene s(scene::shapes::box({20, 20, 5}, 1.0), grey(sigma, eta), {0, 0, 1});
    for (const char* rings : {"4", "40"}) {
      const auto b = radiosity(s, {{0, 0, 5}, {3, -2, 5}}, {{"rings", rings}, {"map", "1024"}});
      for (const auto& v : b) CHECK(v.x / et == doctest::Approx(1).epsilon(0.03));
    }
  }
  SUBCASE("back-lit through d = 2 mean free paths") {
    TestScene s(scene::shapes::box({20, 20, 1}, 0.5), grey(sigma, eta), {0, 0, -1});
    const double d = 2, expected = et * (1 + sigma * d) * std::exp(-sigma * d);
    const auto fine =
        radiosity(s, {{0, 0, 1}}, {{"rings", "200"}, {"map", "1024"}, {"voxels", "40"}});
    const auto paper =
        radiosity(s, {{0, 0, 1}}, {{"rings", "4"}, {"map", "1024"}, {"voxels", "40"}});
    INFO("200 rings: " << fine[0].x / expected << ", 4 rings: " << paper[0].x / expected);
    CHECK(fine[0].x / expected == doctest::Approx(1).epsilon(0.03));
    CHECK(paper[0].x / expected == doctest::Approx(1).epsilon(0.25));
  }
}

TEST_CASE(
    "taulut through a cavity: Eq. 1 against its quadrature over the exact geometry, and "
    "light passes where the cavity thins the cube") {
  // A 2 mm cube, cavity of radius 0.6, sigma_t = 4 / mm, lit from behind (-z), seen at the front.
  const double sigma = 4, h = 1, r = 0.6;
  const glm::dvec3 xo(0, 0, h);
  // sigma^2 / 2 pi int_back face e^{-sigma L(x_in, x_o)} dA, E_t = 1 (eta 1).
  double reference = 0;
  const int n = 800;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const glm::dvec3 xi(-h + 2 * h * (i + 0.5) / n, -h + 2 * h * (j + 0.5) / n, -h);
      reference += std::exp(-sigma * mediumLength(xi, xo, h, r));
    }
  reference *= sigma * sigma / (2 * optics::kPi) * (2 * h / n) * (2 * h / n);
  TestScene cavity(scene::shapes::cubeWithCavity(r), grey(sigma), {0, 0, -1});
  const auto b = radiosity(
      cavity, {xo}, {{"rings", "100"}, {"map", "1024"}, {"voxels", "64"}, {"storage", "march"}});
  INFO("taulut " << b[0].x << ", quadrature " << reference);
  CHECK(b[0].x == doctest::Approx(reference).epsilon(0.08));
  // The solid cube transmits (1 + sigma 2h) e^{-sigma 2h} at most: the cavity lets through more.
  CHECK(b[0].x > 5 * (1 + sigma * 2 * h) * std::exp(-sigma * 2 * h));
}

TEST_CASE("taulut: lut, hierarchical and march agree, fp16 within its stated precision") {
  TestScene s(scene::shapes::cubeWithCavity(0.6), grey(3), {0.3, 0.2, -1});
  const std::vector<glm::dvec3> points{{0, 0, 1}, {0.5, 0.3, 1}, {1, 0.2, -0.1}, {-0.4, 1, 0.6}};
  const lt::KnobList base{{"voxels", "24"}, {"map", "256"}};
  auto with = [&](lt::KnobList extra) {
    extra.insert(extra.begin(), base.begin(), base.end());
    return radiosity(s, points, extra);
  };
  const auto march = with({{"storage", "march"}});
  const auto lut32 = with({{"storage", "lut"}, {"precision", "fp32"}});
  const auto lut16 = with({{"storage", "lut"}, {"precision", "fp16"}});
  const auto tree = with({{"storage", "hierarchical"}, {"cluster", "2"}});
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      INFO("point " << i << " channel " << c);
      CHECK(lut32[i][c] == doctest::Approx(march[i][c]).epsilon(1e-5));
      CHECK(lut16[i][c] == doctest::Approx(march[i][c]).epsilon(0.005));  // tau * 2^-11, tau < 10
      CHECK(tree[i][c] == doctest::Approx(march[i][c]).epsilon(0.25));
    }
}

TEST_CASE("taulut: a material edit in a frame equals a fresh prepare with the new material") {
  TestScene s(scene::shapes::sphere(1.0, 3), grey(2), {0, 0, -1});
  lt::Inclusion core;
  core.surface = scene::shapes::sphere(0.5, 3);
  core.medium.material = grey(10);
  core.contains = [](const glm::dvec3& p) { return glm::length(p) < 0.5; };
  s.scene.inclusions.push_back(core);
  const auto registry = lt::compiledCoreRegistry();
  const lt::Technique& t = registry.get("taulut");
  const lt::KnobValues knobs = t.values({{"voxels", "20"}, {"map", "128"}});
  const lt::ShadeRequest request = at({{0, 0, 1}, {0.6, 0, 0.8}, {0, 0.98, 0.2}});
  lt::Statistics stats;
  auto prepared = t.prepare(s.scene, knobs, stats);
  const auto before = prepared->frame(s.scene, request, stats).radiosity;
  s.scene.medium.material = grey(0.5);
  s.scene.inclusions[0].medium.material = grey(1);
  const auto edited = prepared->frame(s.scene, request, stats).radiosity;
  const auto fresh = t.prepare(s.scene, knobs, stats)->frame(s.scene, request, stats).radiosity;
  for (std::size_t i = 0; i < request.points.size(); ++i) {
    CHECK(edited[i] == fresh[i]);
    CHECK(edited[i] != before[i]);
  }
}

TEST_CASE(
    "taulut hard cases: thin walls, a cavity at the surface, zero density, sigma_a = 0, "
    "an empty grid") {
  auto finite = [](const std::vector<glm::dvec3>& b) {
    for (const auto& v : b)
      for (int c = 0; c < 3; ++c)
        if (!(std::isfinite(v[c]) && v[c] >= 0)) return false;
    return true;
  };
  const std::vector<glm::dvec3> points{{0, 0, 1}, {1, 0.5, 0}, {0.2, -1, 0.1}};
  SUBCASE("a wall one voxel thick, and a cavity reaching the surface (a wall thinner than one)") {
    for (double radius : {0.92, 0.99}) {
      TestScene s(scene::shapes::cubeWithCavity(radius), grey(2), {0.2, 0.1, -1});
      CHECK(finite(radiosity(s, points, {{"voxels", "25"}, {"map", "128"}})));
    }
  }
  SUBCASE("zero density: no medium, no light (the kernel's normalisation is the exit's sigma_t)") {
    TestScene s(scene::shapes::sphere(1.0, 3), grey(2), {0, 0, -1});
    s.scene.medium.density = [](const glm::dvec3&) { return 0.0; };
    s.scene.medium.densityDescription = "zero";
    const auto b = radiosity(s, points, {{"voxels", "16"}, {"map", "128"}});
    for (const auto& v : b) CHECK(v == glm::dvec3(0));
  }
  SUBCASE("a negative density is refused, naming it") {
    TestScene s(scene::shapes::sphere(1.0, 3), grey(2), {0, 0, -1});
    s.scene.medium.density = [](const glm::dvec3&) { return -1.0; };
    s.scene.medium.densityDescription = "test field";
    CHECK_THROWS_WITH_AS(radiosity(s, points, {{"voxels", "8"}}), doctest::Contains("test field"),
                         lt::RequestError);
  }
  SUBCASE("sigma_a = 0 (Spectralon) on tiny and unit objects, and a huge one") {
    auto sphereAt = [&](double scale, const optics::Material& m) {
      TestScene s(scene::shapes::sphere(scale, 3), m, {0.3, 0, -1});
      std::vector<glm::dvec3> scaled;
      for (const auto& p : points) scaled.push_back(p * scale);
      return radiosity(s, scaled, {{"voxels", "16"}, {"map", "256"}});
    };
    for (double scale : {1e-3, 1.0})
      CHECK(finite(sphereAt(scale, *optics::findMaterial("Spectralon"))));
    // 20 m across: a map texel of 80 mm resolves e^{-sigma r} only for a mean free path >= 40 mm.
    CHECK(finite(sphereAt(1e4, grey(1e-3))));
    CHECK_THROWS_WITH_AS(sphereAt(1e4, grey(1)), doctest::Contains("raise map"), lt::RequestError);
  }
  SUBCASE("a shell thinner than a voxel takes no voxel: refused with the fix") {
    // A hollow sphere 0.01 thick; at 4 voxels along 2 mm the centres lie at radii 0.43, 0.83,
    // 1.09 and 1.30.
    scene::TriangleMesh shell = scene::shapes::sphere(1.0, 3);
    const scene::TriangleMesh inner = scene::shapes::sphere(0.99, 3);
    const auto offset = std::uint32_t(shell.positions.size());
    shell.positions.insert(shell.positions.end(), inner.positions.begin(), inner.positions.end());
    for (const auto& t : inner.triangles)
      shell.triangles.push_back({t.x + offset, t.z + offset, t.y + offset});  // facing in
    TestScene s(std::move(shell), grey(2), {0, 0, -1});
    CHECK_THROWS_WITH_AS(radiosity(s, {{0, 0, 1}}, {{"voxels", "4"}}),
                         doctest::Contains("raise voxels"), lt::RequestError);
  }
}

namespace {
/// voxel-single's radiance at the surface points straight below `points` (from +z), seen along +z
/// (a camera far above each point).
std::vector<glm::dvec3> singleScattering(const TestScene& s, const std::vector<glm::dvec3>& points,
                                         const lt::KnobList& knobs) {
  const auto registry = lt::compiledCoreRegistry();
  const lt::Technique& t = registry.get("voxel-single");
  std::vector<glm::dvec3> out;
  for (const auto& p : points) {
    const glm::dvec3 above = p + glm::dvec3(0, 0, 1);
    const auto hit = s.caster->intersect(above, glm::dvec3(0, 0, -1), 0, 2);
    REQUIRE(hit);
    lt::ShadeRequest request;
    reference::ShadingPoint sp;
    sp.position = above - glm::dvec3(0, 0, hit->t);
    sp.triangle = hit->triangle, sp.u = hit->u, sp.v = hit->v, sp.cosOut = 1;
    request.points = {sp};
    scene::PinholeCamera eye =
        scene::PinholeCamera::frame(s.scene.mesh.bounds(), glm::dvec3(0, 0, 1), 8, 8);
    eye.eye = glm::dvec3(p.x, p.y, 1e9);
    request.camera = &eye;
    request.pixels = {0};
    out.push_back(registry.render(t, s.scene, t.values(knobs), request).frame.radiance[0]);
  }
  return out;
}
}  // namespace

TEST_CASE("voxel-single: a slab's single scattering in closed form, lit from behind and in front") {
  // sigma_s = 0.3, sigma_t = 0.8 (g = 0), 2 mm thick, eta 1, seen head-on at its centre.
  optics::Material m;
  m.name = "test";
  m.sigmaA = optics::Rgb<double>(0.5);
  m.sigmaSPrime = optics::Rgb<double>(0.3);
  m.eta = 1.0;
  const double sigmaS = 0.3, sigmaT = 0.8, d = 2;
  const scene::TriangleMesh slab = scene::shapes::box({20, 20, 1}, 1.0);
  SUBCASE("back-lit: sigma_s E d e^{-sigma_t d} / 4 pi") {
    TestScene s(slab, m, {0, 0, -1});
    const double expected = sigmaS * d * std::exp(-sigmaT * d) / (4 * optics::kPi);
    const auto coarse = singleScattering(s, {{0, 0, 1}}, {{"voxels", "40"}, {"samples", "16"}});
    const auto fine = singleScattering(s, {{0, 0, 1}}, {{"voxels", "40"}, {"samples", "256"}});
    INFO("16 depths: " << coarse[0].x / expected << ", 256: " << fine[0].x / expected);
    CHECK(fine[0].x / expected == doctest::Approx(1).epsilon(0.002));
    CHECK(coarse[0].x / expected == doctest::Approx(1).epsilon(0.02));
  }
  SUBCASE("back-lit through eta 1.5 with forward HG g = 0.5: Fresnel in and out, 1/eta^2, p(1)") {
    // Head-on the refraction changes no direction; sigma_s = sigma_s' / (1 - g) = 0.6, sigma_t =
    // 1.1; p_HG(cos 0) = (1 + g) / (4 pi (1 - g)^2).
    optics::Material m15 = m;
    m15.eta = 1.5;
    TestScene s(slab, m15, {0, 0, -1});
    const double g = 0.5, ss = 0.3 / (1 - g), st = 0.5 + ss;
    const double ft = optics::fresnelTransmittance(1.0, 1.5);
    const double expected = ft * ft / (1.5 * 1.5) * ss * d * std::exp(-st * d) * (1 + g) /
                            (4 * optics::kPi * (1 - g) * (1 - g));
    const auto l =
        singleScattering(s, {{0, 0, 1}}, {{"voxels", "40"}, {"samples", "256"}, {"g", "0.5"}});
    CHECK(l[0].x / expected == doctest::Approx(1).epsilon(0.002));
  }
  SUBCASE("front-lit: sigma_s E (1 - e^{-2 sigma_t d}) / (8 pi sigma_t)") {
    TestScene s(slab, m, {0, 0, 1});
    const double expected = sigmaS * (1 - std::exp(-2 * sigmaT * d)) / (8 * optics::kPi * sigmaT);
    const auto coarse = singleScattering(s, {{0, 0, 1}}, {{"voxels", "40"}, {"samples", "4"}});
    const auto fine = singleScattering(s, {{0, 0, 1}}, {{"voxels", "40"}, {"samples", "256"}});
    INFO("4 depths: " << coarse[0].x / expected << ", 256: " << fine[0].x / expected);
    CHECK(fine[0].x / expected == doctest::Approx(1).epsilon(0.002));
    CHECK(coarse[0].x / expected == doctest::Approx(1).epsilon(0.05));
  }
}

TEST_CASE(
    "voxel-single against the path tracer's single scattering (eta 1): a back-lit cube with a "
    "cavity, thick (19 mean free paths) and thin") {
  const auto registry = lt::compiledCoreRegistry();
  for (double sigmaT : {0.2, 1.9}) {
    optics::Material m = grey(sigmaT);
    m.sigmaA = optics::Rgb<double>(0.5 * sigmaT), m.sigmaSPrime = optics::Rgb<double>(0.5 * sigmaT);
    scene::TriangleMesh cube = scene::shapes::cubeWithCavity(0.6);
    cube.scaleToSize(10 * std::sqrt(3.0));  // 10 mm sides
    TestScene s(std::move(cube), m, {0.2, 0.3, -1});
    const scene::PinholeCamera camera =
        scene::PinholeCamera::frame(s.scene.mesh.bounds(), glm::dvec3(0, 0, 1), 24, 24);
    const lt::ShadeRequest pixels = lt::pixelRequest(camera, s.scene);
    auto mean = [&](const char* name, const lt::KnobList& knobs) {
      const lt::Technique& t = registry.get(name);
      const auto l = registry.render(t, s.scene, t.values(knobs), pixels).frame.radiance;
      glm::dvec3 sum(0);
      for (const auto& v : l) sum += v;
      return sum.x / double(l.size());
    };
    const double truth =
        mean("pathtrace",
             {{"spp", "1024"}, {"orders", "single"}, {"subsurface", "1"}, {"boundary", "matched"}});
    const double single = mean("voxel-single", {{"voxels", "64"}});
    INFO("sigma_t " << sigmaT << ": voxel-single / path tracer = " << single / truth);
    CHECK(single / truth == doctest::Approx(1).epsilon(0.03));
  }
}

TEST_CASE(
    "A coefficient field (a scan through a transfer function) renders as the same medium "
    "given as material x density: voxel-single and taulut exactly, the path tracer within "
    "its noise") {
  // A sphere whose left half has density 1 and right half 0.25 of a grey material, once as a
  // density field and once as a field of coefficients.
  const optics::Material m = grey(1.5);
  auto density = [](const glm::dvec3& p) { return p.x < 0 ? 1.0 : 0.25; };
  TestScene dense(scene::shapes::sphere(2.0, 3), m, {0.3, 0.2, -1});
  dense.scene.medium.density = density;
  dense.scene.medium.densityDescription = "halves";
  TestScene field(scene::shapes::sphere(2.0, 3), m, {0.3, 0.2, -1});
  field.scene.medium.coefficients = [&](const glm::dvec3& p) {
    return lt::Coefficients{glm::dvec3(m.sigmaA) * density(p),
                            glm::dvec3(m.sigmaSPrime) * density(p)};
  };
  field.scene.medium.maxSigmaT = glm::dvec3(m.sigmaA + m.sigmaSPrime);
  field.scene.medium.densityDescription = "halves as coefficients";
  const auto registry = lt::compiledCoreRegistry();
  const scene::PinholeCamera camera =
      scene::PinholeCamera::frame(dense.scene.mesh.bounds(), glm::dvec3(0, 0, 1), 16, 16);
  auto mean = [&](const TestScene& s, const char* name, const lt::KnobList& knobs) {
    const lt::Technique& t = registry.get(name);
    const auto l = registry.render(t, s.scene, t.values(knobs), lt::pixelRequest(camera, s.scene))
                       .frame.radiance;
    glm::dvec3 sum(0);
    for (const auto& v : l) sum += v;
    return sum / double(l.size());
  };
  for (const char* name : {"voxel-single", "taulut"}) {
    const lt::KnobList knobs{{"voxels", "24"}};
    const glm::dvec3 a = mean(dense, name, knobs), b = mean(field, name, knobs);
    INFO(std::string(name));
    for (int c = 0; c < 3; ++c) CHECK(b[c] == doctest::Approx(a[c]).epsilon(1e-6));
  }
  const lt::KnobList pt{{"spp", "256"}, {"boundary", "matched"}, {"subsurface", "1"}};
  const glm::dvec3 a = mean(dense, "pathtrace", pt), b = mean(field, "pathtrace", pt);
  for (int c = 0; c < 3; ++c) CHECK(b[c] == doctest::Approx(a[c]).epsilon(0.03));
}
