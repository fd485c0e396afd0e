#include <doctest/doctest.h>

#include <lucent/optics/materials.hpp>
#include <lucent/technique/prepared_cache.hpp>

namespace {
namespace lt = lucent::technique;

/// Radiance = the prepare-phase knob `level` x the frame-phase knob `gain` x the light's
/// irradiance (read by the frame) x how many prepares ran: a reused prepare shows in the value.
lt::Technique countingTechnique(int& prepares, bool dynamicMaterial) {
  lt::Technique t;
  t.name = "test-counting";
  t.knobs = {lt::KnobSpec::real("level", "1", 0, 10, "", "prepared value", lt::Phase::Prepare),
             lt::KnobSpec::real("gain", "1", 0, 10, "", "frame gain")};
  t.capabilities.dynamicMaterial = dynamicMaterial;
  t.capabilities.pointLights = t.capabilities.environmentLights = false;
  struct Counted final : lt::Prepared {
    double value;
    explicit Counted(double v) : value(v) {}
    lt::FrameResult frame(const lt::SceneDescription& scene, const lt::ShadeRequest& request,
                          lt::Statistics&) override {
      const double e = std::get<lucent::scene::DirectionalLight>(scene.lights.at(0)).irradiance.x;
      lt::FrameResult out;
      out.radiance.assign(request.points.size(), glm::dvec3(value * e));
      return out;
    }
  };
  t.prepare = [&prepares](const lt::SceneDescription&, const lt::KnobValues& knobs,
                          lt::Statistics& stats) {
    ++prepares;
    stats.samples = 7;
    return std::make_unique<Counted>(knobs.real("level") * prepares);
  };
  return t;
}

lt::SceneDescription litScene(double irradiance) {
  lt::SceneDescription scene;
  scene.lights = {lucent::scene::DirectionalLight{{0, 0, 1}, glm::dvec3(irradiance)}};
  scene.medium.material = *lucent::optics::findMaterial("skin1");
  return scene;
}
}  // namespace

TEST_CASE("A kept prepare is reused for frame-phase changes and rebuilt for the rest") {
  int prepares = 0;
  lt::Registry registry;
  registry.add(countingTechnique(prepares, /*dynamicMaterial=*/false));
  const lt::Technique& t = registry.get("test-counting");
  lt::ShadeRequest request;
  request.points.resize(2);
  lt::PreparedCache cache;
  lt::SceneDescription scene = litScene(1);

  auto value = [&](const lt::KnobList& knobs, const std::string& geometry) {
    return cache.render(registry, t, scene, t.values(knobs), request, geometry).frame.radiance[1].x;
  };
  CHECK(value({}, "mesh A") == 1);
  CHECK_FALSE(cache.reused());
  CHECK(value({{"gain", "3"}}, "mesh A") == 1);  // a frame knob: the same prepare
  CHECK(cache.reused());
  scene.lights = litScene(4).lights;  // dynamicLight: the frame reads the new light
  CHECK(value({}, "mesh A") == 4);
  CHECK(cache.reused());
  const lt::Rendered again = cache.render(registry, t, scene, t.values(), request, "mesh A");
  CHECK(again.stats.samples == 7);  // the prepare's statistics travel with it
  CHECK(again.stats.figures.at("prepare_reused") == 1);

  CHECK(value({{"level", "2"}}, "mesh A") == 2 * 2 * 4);  // a prepare knob: prepare 2
  CHECK_FALSE(cache.reused());
  CHECK(value({{"level", "2"}}, "mesh B") == 2 * 3 * 4);  // new geometry: prepare 3
  scene.medium.material = *lucent::optics::findMaterial("marble");
  CHECK(value({{"level", "2"}}, "mesh B") == 2 * 4 * 4);  // !dynamicMaterial: prepare 4
  CHECK(prepares == 4);
  cache.clear();
  CHECK(value({{"level", "2"}}, "mesh B") == 2 * 5 * 4);
}

TEST_CASE("A technique whose frame takes the material keeps its prepare across a material change") {
  int prepares = 0;
  lt::Registry registry;
  registry.add(countingTechnique(prepares, /*dynamicMaterial=*/true));
  const lt::Technique& t = registry.get("test-counting");
  lt::ShadeRequest request;
  request.points.resize(1);
  lt::PreparedCache cache;
  lt::SceneDescription scene = litScene(1);
  cache.render(registry, t, scene, t.values(), request, "mesh");
  scene.medium.material = *lucent::optics::findMaterial("marble");
  cache.render(registry, t, scene, t.values(), request, "mesh");
  CHECK(cache.reused());
  CHECK(prepares == 1);
}
