// Texture-space importance sampling and the hybrid method against independent references: the dense
// midpoint-rule truth (dipole_truth.hpp), the atlas's own exhaustive texel sum, and the flat-slab
// closed form.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>
#include <utility>

#include <lucent/atlas/hybrid.hpp>
#include <lucent/atlas/texture_atlas.hpp>
#include <lucent/image/metrics.hpp>
#include <lucent/reference/dipole_truth.hpp>
#include <lucent/scene/shapes.hpp>
#include <lucent/util/rng.hpp>

#include "small_scene.hpp"

using namespace lucent;
using test::dipoleOf;
using test::SmallScene;

namespace {
/// A deliberately bad parameterization: every triangle its own chart, each shrunk by a random
/// factor in [0.2, 1] inside its own grid cell (area ratios vary 25x across the surface).
std::vector<glm::dvec2> randomlyScaledTriangleCharts(const scene::TriangleMesh& mesh) {
  const std::size_t n = mesh.triangles.size();
  const int cells = int(std::ceil(std::sqrt(double(n))));
  util::Rng rng(7);
  std::vector<glm::dvec2> uv;
  for (std::size_t t = 0; t < n; ++t) {
    const glm::dvec2 cell(double(t % cells), double(t / cells));
    const double s = 0.2 + 0.8 * rng.uniform();
    const glm::dvec2 o = (cell + 0.5 * (1 - s) * glm::dvec2(1)) / double(cells);
    const double k = 0.98 * s / cells;
    // Keep the triangle's shape (edge lengths) up to the scale: place a at 0, b on the x axis.
    const glm::dvec3 a(mesh.positions[mesh.triangles[t].x]), b(mesh.positions[mesh.triangles[t].y]),
        c(mesh.positions[mesh.triangles[t].z]);
    const double ab = glm::length(b - a);
    const glm::dvec3 ex = (b - a) / ab;
    const double cx = glm::dot(c - a, ex), cy = glm::length((c - a) - cx * ex);
    const double span = std::max({ab, std::abs(cx), cy, std::abs(ab - cx)});
    uv.push_back(o + 0.01 * k * glm::dvec2(1));
    uv.push_back(o + k * glm::dvec2(ab, 0) / span * 0.98 + 0.01 * k * glm::dvec2(1));
    uv.push_back(o + k * glm::dvec2(std::max(cx, 0.0), cy) / span * 0.98 +
                 0.01 * k * glm::dvec2(1));
  }
  return uv;
}

atlas::IrradianceAtlas irradianceOf(const SmallScene& s, const atlas::TextureAtlas& a) {
  return atlas::renderIrradianceAtlas(a, s.mesh, s.normals, s.lights, *s.caster, s.irr,
                                      util::tbbFor);
}

glm::dvec3 truthPower(const SmallScene& s, double spacing) {
  const auto samples = reference::buildSurfaceSamples(s.mesh, spacing);
  const reference::DipoleTruth<double> truth(samples, dipoleOf<double>("skin1"), s.lights,
                                             *s.caster, s.irr, util::tbbFor);
  return truth.stats().transmittedPower;
}

double worstRelative(const glm::dvec3& a, const glm::dvec3& b) {
  double w = 0;
  for (int c = 0; c < 3; ++c) w = std::max(w, std::abs(a[c] / b[c] - 1));
  return w;
}
}  // namespace

TEST_CASE("Atlas integral of E' = surface integral of E (Eq. 6-7), for any parameterization") {
  const SmallScene torus(scene::shapes::torus(1.0, 0.4, 64, 32), 20.0, 32);
  const glm::dvec3 surface = truthPower(torus, 0.05);  // dense midpoint rule over the mesh itself
  atlas::AtlasOptions o;
  o.resolution = 1024;
  const auto charts = atlas::buildTextureAtlas(torus.mesh, o);
  const double builtIn = worstRelative(irradianceOf(torus, charts).totalPower, surface);
  const auto scattered =
      atlas::atlasFromUvs(torus.mesh, randomlyScaledTriangleCharts(torus.mesh), 1024);
  REQUIRE(scattered.stats.areaStretchMax / scattered.stats.areaStretchMin > 10);
  const auto scatteredIrr = irradianceOf(torus, scattered);
  const double distorted = worstRelative(scatteredIrr.totalPower, surface);
  // Control: without the A_S/A_T factor (one common scale for all texels) the distorted atlas is
  // wrong.
  glm::dvec3 naive(0);
  std::size_t owned = 0;
  for (std::size_t i = 0; i < scatteredIrr.power.size(); ++i) {
    const auto t = scattered.texelTriangle[i];
    if (t < 0) continue;
    ++owned;
    naive += glm::dvec3(scatteredIrr.power[i]) * double(scattered.texelCount[std::size_t(t)]) /
             torus.mesh.triangleArea(std::size_t(t));
  }
  naive *= torus.mesh.surfaceArea() / double(owned);
  const double withoutRatio = worstRelative(naive, surface);
  INFO("relative error of the atlas integral: built-in charts "
       << builtIn << ", random one-triangle charts " << distorted << ", same without A_S/A_T "
       << withoutRatio);
  CHECK(builtIn < 2e-3);
  CHECK(distorted < 5e-3);
  CHECK(withoutRatio > 10 * distorted);
}

TEST_CASE("Eq. 10 weights are unbiased: the mean over seeds equals the exhaustive texel sum") {
  const SmallScene s(scene::shapes::sphere(1.0, 4), 10.0, 32);
  atlas::AtlasOptions o;
  o.resolution = 256;
  const auto irr = irradianceOf(s, atlas::buildTextureAtlas(s.mesh, o));
  const auto d = dipoleOf<double>("marble");
  const glm::dvec3 xo(s.mesh.positions[17]);
  // The integral the sampler estimates, summed over every texel (texel centres, as sampled below).
  glm::dvec3 exact(0);
  for (std::size_t i = 0; i < irr.power.size(); ++i)
    if (irr.importance[i] > 0)
      exact +=
          glm::dvec3(irr.power[i]) * d.rd(glm::length(glm::dvec3(irr.surface->position[i]) - xo));
  for (const auto sampler : {atlas::TexelSampler::Mipmap, atlas::TexelSampler::RowMajor}) {
    atlas::SamplingOptions so;
    so.samples = 64;
    so.sampler = sampler;
    so.pattern = atlas::SamplePattern::Independent;
    so.jitterInTexel = false;
    const int runs = 400;
    glm::dvec3 sum(0), sq(0);
    for (int r = 0; r < runs; ++r) {
      so.seed = std::uint64_t(r + 1);
      const auto samples = atlas::drawImportanceSamples(irr, so);
      glm::dvec3 b(0);
      for (std::size_t i = 0; i < samples.size(); ++i) {
        const double dist = glm::length(glm::dvec3(samples.x[i], samples.y[i], samples.z[i]) - xo);
        for (int c = 0; c < 3; ++c) b[c] += double(samples.w[c][i]) * d.rd(dist)[c];
      }
      sum += b, sq += b * b;
    }
    const glm::dvec3 mean = sum / double(runs);
    for (int c = 0; c < 3; ++c) {
      const double se = std::sqrt(std::max(0.0, sq[c] / runs - mean[c] * mean[c]) / runs);
      INFO("channel " << c << ": mean " << mean[c] << " exact " << exact[c] << " s.e. " << se);
      CHECK(std::abs(mean[c] - exact[c]) < 4 * se + 1e-6 * exact[c]);
      CHECK(se < 0.1 * exact[c]);
    }
  }
}

TEST_CASE(
    "TSIS on a 10 mm skin1 sphere, 1600 samples: RMSE <= 0.010 against the truth, per vertex and "
    "hybrid too") {
  const SmallScene s(scene::shapes::sphere(1.0, 5), 10.0, 160);
  const auto dd = dipoleOf<double>("skin1");
  const auto df = dipoleOf<float>("skin1");
  const image::Image truth = s.render(df, 0.5 * df.minMeanFreePath());
  const auto hits = reference::primaryHits(s.camera, s.mesh, s.normals, *s.caster, util::tbbFor);
  atlas::AtlasOptions o;
  const auto a = atlas::buildTextureAtlas(s.mesh, o);
  const auto irr = irradianceOf(s, a);
  atlas::SamplingOptions so;
  so.samples = 1600;
  const optics::RdTable<float> table(df, float(s.mesh.bounds().diagonal()));
  const atlas::TsisEvaluator tsis(atlas::drawImportanceSamples(irr, so), table, 1.3f);
  const image::Image perPixel = reference::renderTruth(tsis, s.camera, hits, util::tbbFor);
  const atlas::PerVertexShading<atlas::TsisEvaluator> pv(tsis, s.mesh, util::tbbFor);
  const image::Image perVertex = reference::renderTruth(pv, s.camera, hits, util::tbbFor);

  const double rp = atlas::hybridRp(dd, 0.05);
  const double diag = s.mesh.bounds().diagonal();
  const atlas::HybridProfiles profiles(dd, rp, diag);
  std::vector<atlas::TranslucentShadowMap> maps;
  for (const auto& l : s.lights)
    maps.emplace_back(l, s.mesh, s.normals, *s.caster, s.irr, 512, util::tbbFor);
  const atlas::LocalTermEvaluator local(
      std::move(maps),
      atlas::makeRingFilter([&](double r) { return glm::dvec3(profiles.local(float(r))); }, 20, 20,
                            diag),
      profiles.local, 1.3f);
  so.samples = 900;
  const atlas::TsisEvaluator global(atlas::drawImportanceSamples(irr, so), profiles.global, 1.3f);
  const image::Image hybrid =
      reference::renderTruth(atlas::HybridEvaluator(local, global), s.camera, hits, util::tbbFor);

  const auto ePixel = image::compareImages(perPixel, truth),
             eVertex = image::compareImages(perVertex, truth),
             eHybrid = image::compareImages(hybrid, truth);
  INFO("RMSE (tone-mapped): per pixel "
       << ePixel.rmseToneMapped << ", per vertex " << eVertex.rmseToneMapped << ", hybrid 900+401 "
       << eHybrid.rmseToneMapped << "; relative RMS " << ePixel.relativeRms << " "
       << eVertex.relativeRms << " " << eHybrid.relativeRms);
  CHECK(ePixel.rmseToneMapped <= 0.010);
  CHECK(eVertex.rmseToneMapped <= 0.010);
  CHECK(eHybrid.rmseToneMapped <= 0.010);
  CHECK(ePixel.coverageMismatch == 0);
}

TEST_CASE("Translucent shadow map on a flat slab: the ring filter returns E_t x int Rd 2 pi r dr") {
  // Semi-infinite limit as in the truth's slab test: every filter sample lies on the lit plane.
  // 1 mm cells: the smoothed normals along the top face's rim (which lower E there) cover 3 % of
  // it.
  scene::TriangleMesh slab = scene::shapes::box(glm::dvec3(60, 60, 10), 1.0);
  raycast::EmbreeRayCaster caster(slab);
  const auto d = dipoleOf<double>("skin1");
  const scene::Light light = scene::DirectionalLight{glm::dvec3(0, 0, 1), glm::dvec3(1)};
  scene::IrradianceSettings irr;
  irr.rayEpsilon = 1e-4;
  const atlas::TranslucentShadowMap map(light, slab, slab.vertexNormals(), caster, irr, 2048,
                                        util::tbbFor);
  auto rd = [&](double r) { return glm::dvec3(d.rd(r)); };
  const auto ring = atlas::makeRingFilter(rd, 24, 16, 100.0, 0.9995);
  const glm::dvec3 b = map.filter(glm::dvec3(0.0123, -0.0371, 10.0), ring, rd);
  const double et = optics::fresnelTransmittance(1.0, 1.3);
  const auto expected = d.cumulative(ring.outerRadius) * et;
  INFO("B " << b.x << " " << b.y << " " << b.z << " expected " << expected.x << " " << expected.y
            << " " << expected.z);
  CHECK(worstRelative(b, expected) < 0.02);
  // The table path the hybrid uses (gathered taps, vectorised sum) against the same closed form.
  const auto table = optics::radialTable(optics::Profile<double>(d), 100.0f);
  const glm::dvec3 bTable =
      map.filterTable(glm::dvec3(0.0123, -0.0371, 10.0), ring, reference::PlanarRadialTable(table));
  CHECK(worstRelative(bTable, expected) < 0.02);
  // And the map holds what the light puts in: E_t times the lit top face (120 x 120 mm).
  CHECK(map.totalPower().x == doctest::Approx(et * 120 * 120).epsilon(0.01));
}

TEST_CASE(
    "The ring filter's table path equals the per-tap estimator, where the map is partly "
    "covered and off it") {
  // A sphere fills a disc of the map: points near its rim have taps on empty texels and off the
  // map. (1e-4: a tap on a texel edge may land in the neighbouring texel in one of the two paths.)
  SmallScene s(scene::shapes::sphere(1.0, 3), 10.0, 24);
  const auto d = dipoleOf<double>("skin1");
  const auto table = optics::radialTable(optics::Profile<double>(d), 20.0f);
  const reference::PlanarRadialTable planar(table);
  auto f = [&](double r) { return glm::dvec3(table(float(r))); };
  const auto ring = atlas::makeRingFilter(f, 12, 10, 20.0);
  const atlas::TranslucentShadowMap map(s.lights[1], s.mesh, s.normals, *s.caster, s.irr, 96);
  util::Rng rng(7);
  int nonZero = 0;
  for (int i = 0; i < 300; ++i) {
    const glm::dvec3 x =
        7.0 * glm::dvec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
    const glm::dvec3 perTap = map.filter(x, ring, f), gathered = map.filterTable(x, ring, planar);
    nonZero += perTap.x > 0;
    INFO("x " << x.x << " " << x.y << " " << x.z << " per tap " << perTap.x << " gathered "
              << gathered.x);
    for (int c = 0; c < 3; ++c)
      CHECK(std::abs(gathered[c] - perTap[c]) <= 1e-4 * std::max(perTap[c], 1e-30) + 1e-30);
  }
  CHECK(nonZero > 100);  // the points did reach the surface
}

TEST_CASE("The ring filter's turn rotates its spokes: a turn of one spoke visits the same texels") {
  scene::TriangleMesh slab = scene::shapes::box(glm::dvec3(60, 60, 10), 1.0);
  raycast::EmbreeRayCaster caster(slab);
  const scene::Light light = scene::DirectionalLight{glm::dvec3(0, 0, 1), glm::dvec3(1)};
  const atlas::TranslucentShadowMap map(light, slab, slab.vertexNormals(), caster, {}, 512);
  const int perRing = 12;
  const auto ring =
      atlas::makeRingFilter([](double r) { return glm::dvec3(std::exp(-r)); }, 6, perRing, 30.0);
  const glm::dvec3 xo(0.37, -0.21, 10.0);
  auto visited = [&](double turn) {
    std::multiset<std::pair<std::size_t, std::size_t>> taps;  // (stratum, texel)
    map.forEachTap(
        xo, ring,
        [&](std::size_t i, std::size_t k, double) {
          taps.insert({k, i});
        },
        turn);
    return taps;
  };
  const auto none = visited(0), oneSpoke = visited(2 * optics::kPi / perRing),
             halfSpoke = visited(optics::kPi / perRing);
  REQUIRE(none.size() == std::size_t(6 * perRing + 1));  // every tap on the lit face
  std::vector<std::pair<std::size_t, std::size_t>> differ;
  std::set_symmetric_difference(none.begin(), none.end(), oneSpoke.begin(), oneSpoke.end(),
                                std::back_inserter(differ));
  CHECK(differ.size() <= 2);  // a tap within rounding of a texel edge may fall either side
  differ.clear();
  std::set_symmetric_difference(none.begin(), none.end(), halfSpoke.begin(), halfSpoke.end(),
                                std::back_inserter(differ));
  CHECK(differ.size() > 20);  // half a spoke moves the taps
}

TEST_CASE("No light reaching the surface: no samples, black image, no division by zero") {
  SmallScene s(scene::shapes::sphere(1.0, 3), 10.0, 24);
  s.lights = {scene::DirectionalLight{glm::dvec3(0, 0, 1), glm::dvec3(0)}};
  atlas::AtlasOptions o;
  o.resolution = 128;
  const auto irr = irradianceOf(s, atlas::buildTextureAtlas(s.mesh, o));
  CHECK(irr.totalPower == glm::dvec3(0));
  const auto samples = atlas::drawImportanceSamples(irr, {});
  CHECK(samples.size() == 0);
  const atlas::TsisEvaluator eval(samples, dipoleOf<float>("skin1"));
  const glm::dvec3 b = eval.radiance(glm::dvec3(s.mesh.positions[0]), 0.7);
  CHECK(b == glm::dvec3(0));
}

TEST_CASE(
    "Hard cases: tsis and hybrid stay finite for spectralon, 0.01 mm and 10 m objects, a thin "
    "twirl") {
  struct Case {
    const char* what;
    scene::TriangleMesh mesh;
    double size;
    const char* material;
  };
  const Case cases[] = {{"spectralon", scene::shapes::sphere(1, 3), 10, "spectralon"},
                        {"0.01 mm", scene::shapes::sphere(1, 3), 0.01, "skin1"},
                        {"10 m", scene::shapes::sphere(1, 3), 1e4, "cream"},
                        {"thin twirl", scene::shapes::twirl(), 30, "ketchup"}};
  for (const auto& c : cases) {
    CAPTURE(c.what);
    const SmallScene s(c.mesh, c.size, 32);
    const auto dd = dipoleOf<double>(c.material);
    const auto df = dipoleOf<float>(c.material);
    atlas::AtlasOptions o;
    o.resolution = 256;
    const auto irr = irradianceOf(s, atlas::buildTextureAtlas(s.mesh, o));
    atlas::SamplingOptions so;
    so.samples = 256;
    const double diag = s.mesh.bounds().diagonal();
    const atlas::TsisEvaluator tsis(atlas::drawImportanceSamples(irr, so), df);
    const atlas::HybridProfiles profiles(dd, atlas::hybridRp(dd, 0.05), diag);
    std::vector<atlas::TranslucentShadowMap> maps;
    for (const auto& l : s.lights)
      maps.emplace_back(l, s.mesh, s.normals, *s.caster, s.irr, 64, util::tbbFor);
    const atlas::LocalTermEvaluator local(
        std::move(maps),
        atlas::makeRingFilter([&](double r) { return glm::dvec3(profiles.local(float(r))); }, 4, 4,
                              diag),
        profiles.local, float(dd.eta));
    const atlas::TsisEvaluator global(atlas::drawImportanceSamples(irr, so), profiles.global,
                                      float(dd.eta));
    const atlas::HybridEvaluator hybrid(local, global);
    const auto hits = reference::primaryHits(s.camera, s.mesh, s.normals, *s.caster, util::tbbFor);
    double lit = 0;
    for (const auto& img : {reference::renderTruth(tsis, s.camera, hits, util::tbbFor),
                            reference::renderTruth(hybrid, s.camera, hits, util::tbbFor)})
      for (const auto& p : img.pixels)
        for (int k = 0; k < 3; ++k) {
          REQUIRE(std::isfinite(p[k]));
          REQUIRE(p[k] >= 0);
          lit += p[k];
        }
    CHECK(lit > 0);
  }
}
