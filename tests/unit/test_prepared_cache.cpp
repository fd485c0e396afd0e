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

/// The counting technique in a registry of its own, a lit scene, two points and a cache.
struct Counting {
  int prepares = 0;
  lt::Registry registry;
  lt::ShadeRequest request;
  lt::PreparedCache cache;
  lt::SceneDescription scene = litScene(1);
  explicit Counting(bool dynamicMaterial) {
    registry.add(countingTechnique(prepares, dynamicMaterial));
    request.points.resize(2);
  }
  const lt::Technique& technique() const { return registry.get("test-counting"); }
  /// The second point's radiance, rendered through the cache.
  double value(const lt::KnobList& knobs, const std::string& geometry) {
    const lt::Technique& t = technique();
    return cache.render(registry, t, scene, t.values(knobs), request, geometry).frame.radiance[1].x;
  }
};
}  // namespace

TEST_CASE("A kept prepare is reused for frame-phase changes and rebuilt for the rest") {
  Counting c(/*dynamicMaterial=*/false);
  CHECK(c.value({}, "mesh A") == 1);
  CHECK_FALSE(c.cache.reused());
  CHECK(c.value({{"gain", "3"}}, "mesh A") == 1);  // a frame knob: the same prepare
  CHECK(c.cache.reused());
  c.scene.lights = litScene(4).lights;  // dynamicLight: the frame reads the new light
  CHECK(c.value({}, "mesh A") == 4);
  CHECK(c.cache.reused());
  const lt::Rendered again = c.cache.render(c.registry, c.technique(), c.scene,
                                            c.technique().values(), c.request, "mesh A");
  CHECK(again.stats.samples == 7);  // the prepare's statistics travel with it
  CHECK(again.stats.figures.at("prepare_reused") == 1);

  CHECK(c.value({{"level", "2"}}, "mesh A") == 2 * 2 * 4);  // a prepare knob: prepare 2
  CHECK_FALSE(c.cache.reused());
  CHECK(c.value({{"level", "2"}}, "mesh B") == 2 * 3 * 4);  // new geometry: prepare 3
  c.scene.medium.material = *lucent::optics::findMaterial("marble");
  CHECK(c.value({{"level", "2"}}, "mesh B") == 2 * 4 * 4);  // !dynamicMaterial: prepare 4
  CHECK(c.prepares == 4);
  c.cache.clear();
  CHECK(c.value({{"level", "2"}}, "mesh B") == 2 * 5 * 4);
}

TEST_CASE("A technique whose frame takes the material keeps its prepare across a material change") {
  Counting c(/*dynamicMaterial=*/true);
  c.value({}, "mesh");
  c.scene.medium.material = *lucent::optics::findMaterial("marble");
  c.value({}, "mesh");
  CHECK(c.cache.reused());
  CHECK(c.prepares == 1);
}
