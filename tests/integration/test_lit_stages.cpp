// The light stages a frame keeps (technique/lit_stages.hpp): for every technique that declares it
// keeps them (Capabilities::keepsLightStages),
// a frame from a new view reuses them and gives exactly what a fresh prepare and frame give there;
// a light or material change builds them again and gives what a fresh run gives; eval=vertex sums
// the vertices once per light.
#include <doctest/doctest.h>

#include <set>
#include <string>

#include <lucent/scene/shapes.hpp>
#include <lucent/technique/registry.hpp>

#include "technique/core_registry.hpp"

#include "small_scene.hpp"
#include "util/tbb_parallel.hpp"

namespace {
namespace lt = lucent::technique;
using lucent::test::SmallScene;

lt::SceneDescription describe(const SmallScene& s, const char* material) {
  lt::SceneDescription scene;
  scene.meshName = "sphere";
  scene.mesh = s.mesh;
  scene.vertexNormals = s.normals;
  scene.caster = s.caster.get();
  scene.lights = s.lights;
  scene.medium.material = *lucent::optics::findMaterial(material);
  scene.parallelFor = lucent::util::tbbFor;
  return scene;
}

/// A fresh prepare and one frame at `request` (what a run without kept stages computes).
std::vector<glm::dvec3> fresh(const lt::Technique& t, const lt::SceneDescription& scene,
                              const lt::KnobValues& knobs, const lt::ShadeRequest& request) {
  lt::Statistics stats;
  const auto prepared = t.prepare(scene, knobs, stats);
  return prepared->frame(scene, request, stats).radiosity;
}

void checkEqual(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
  REQUIRE(a.size() == b.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i) differ += a[i] != b[i];
  CHECK(differ == 0);
}
}  // namespace

TEST_CASE(
    "Kept light stages: a view change reuses them exactly, a light or material change "
    "builds them again") {
  SmallScene s(lucent::scene::shapes::sphere(1.0, 4), 20, 24);
  lt::SceneDescription scene = describe(s, "skin1");
  const lt::Registry registry = lt::compiledCoreRegistry();
  lucent::scene::PinholeCamera turned = s.camera;
  turned.eye = glm::dvec3(-turned.eye.z, turned.eye.y, turned.eye.x);  // a quarter turn
  const lt::ShadeRequest first = lt::pixelRequest(s.camera, scene);
  const lt::ShadeRequest second = lt::pixelRequest(turned, scene);
  REQUIRE(first.points.size() > 100);
  std::set<std::string> keeping;
  for (const lt::Technique& t : registry.all()) {
    if (!t.capabilities.keepsLightStages) continue;
    keeping.insert(t.name);
    for (const char* where : {"pixel", "vertex"}) {
      INFO(t.name << " eval=" << where);
      lt::KnobList given(t.quickKnobs.begin(), t.quickKnobs.end());
      if (t.knob("eval"))
        given.emplace_back("eval", where);
      else if (std::string(where) == "vertex")
        continue;
      const lt::KnobValues knobs = t.values(given);
      lt::SceneDescription lit = describe(s, "skin1");
      lt::Statistics stats;
      const auto prepared = t.prepare(lit, knobs, stats);
      lt::Statistics one, two, three, four;
      prepared->frame(lit, first, one);
      CHECK(one.figures.at("light_stages_reused") == 0);
      checkEqual(prepared->frame(lit, second, two).radiosity, fresh(t, lit, knobs, second));
      CHECK(two.figures.at("light_stages_reused") == 1);
      CHECK(two.samples == one.samples);  // the kept stages report what they were built with
      lit.lights[1] = lucent::scene::DirectionalLight{glm::dvec3(0, 1, 0), glm::dvec3(0.3)};
      checkEqual(prepared->frame(lit, second, three).radiosity, fresh(t, lit, knobs, second));
      CHECK(three.figures.at("light_stages_reused") == 0);
      lit.medium.material = *lucent::optics::findMaterial("marble");
      checkEqual(prepared->frame(lit, second, four).radiosity, fresh(t, lit, knobs, second));
      CHECK(four.figures.at("light_stages_reused") == 0);
    }
  }
  // The techniques whose light stages are built to be kept say so (a new one may join them).
  for (const char* name : {"tsis", "hybrid", "tsm", "taulut"}) {
    INFO(name);
    CHECK(keeping.count(name) == 1);
  }
}
