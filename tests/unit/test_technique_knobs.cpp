// Typed knobs and the registry's own rules: values are checked against their spec before any work,
// the CamelCase names front ends derive are unique, and capability checks name the techniques that
// can.
#include <doctest/doctest.h>

#include <lucent/technique/registry.hpp>

#include "technique/core_registry.hpp"

using namespace lucent::technique;

namespace {
std::vector<KnobSpec> specs() {
  return {KnobSpec::integer("samples", 16, 1, 4096, "n"),
          KnobSpec::real("bound", "0.05", 0, kUnbounded, "mm^-1", "c", Phase::Frame, true),
          KnobSpec::choice("sampler", {"mip", "row"}, "s"),
          KnobSpec::outputFile("vtu", ".vtu", "o")};
}
std::string errorOf(const KnobList& given) {
  try {
    KnobValues(specs(), given, "t");
  } catch (const RequestError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE(
    "Knob values: defaults, typed reads, and each kind's check with the range in the message") {
  const KnobValues v(specs(), {{"samples", "64"}}, "t");
  CHECK(v.integer("samples") == 64);
  CHECK(v.real("bound") == doctest::Approx(0.05));
  CHECK(v.text("sampler") == "mip");
  CHECK(v.summary(true) == "samples=64");
  CHECK(errorOf({{"samples", "0"}}) ==
        "technique 't' knob samples must be an integer in [1, 4096], not 0");
  CHECK(errorOf({{"samples", "2.5"}}) ==
        "technique 't' knob samples must be an integer in [1, 4096], not 2.5");
  CHECK(errorOf({{"samples", "nan"}}) ==
        "technique 't' knob samples must be a finite number, not 'nan'");
  CHECK(errorOf({{"bound", "0"}}) == "technique 't' knob bound must be > 0, not 0");
  CHECK(errorOf({{"sampler", "cdf"}}) ==
        "technique 't' knob sampler must be mip or row, not 'cdf'");
  CHECK(errorOf({{"vtu", "graph.txt"}}) ==
        "technique 't' knob vtu='graph.txt' must name a .vtu file");
  CHECK(errorOf({{"warp", "9"}}) ==
        "technique 't' has no knob 'warp'; its knobs are: samples, bound, sampler, vtu");
  CHECK(errorOf({{"vtu", "g.vtu"}}).empty());
}

TEST_CASE(
    "CamelCase names are mechanical, and the registry refuses knobs whose CamelCase names "
    "collide") {
  CHECK(camelCase("chart-angle") == "ChartAngle");
  CHECK(camelCase("jensen-buhler") == "JensenBuhler");
  CHECK(camelCase("K") == "K");
  Technique t;
  t.name = "clash";
  t.knobs = {KnobSpec::integer("c", 1, 0, 2, ""), KnobSpec::integer("C", 1, 0, 2, "")};
  Registry r;
  CHECK_THROWS_AS(r.add(t), std::logic_error);
  t.knobs.pop_back();
  r.add(t);
  CHECK_THROWS_AS(r.add(t), std::logic_error);  // the same name twice
}

TEST_CASE(
    "Every core technique: valid defaults, unique knob names, and a default sweep over its own "
    "knobs") {
  const Registry r = compiledCoreRegistry();
  CHECK(r.all().size() == 10);
  for (const auto& t : r.all()) {
    INFO(t.name);
    CHECK_FALSE(t.summary.empty());
    CHECK_FALSE(t.paper.empty());
    REQUIRE_FALSE(t.defaultSweep.empty());
    for (const auto& s : t.defaultSweep) {
      REQUIRE(t.knob(s.knob) != nullptr);
      for (const auto& v : s.values) CHECK_NOTHROW(t.values({{s.knob, v}}));
    }
    CHECK_NOTHROW(t.values(t.referenceKnobs));
  }
  CHECK_THROWS_WITH_AS(
      r.get("magic"), doctest::Contains("available: reference, jensen-buhler, tsis"), RequestError);
}

TEST_CASE("Capabilities: the unmet requirements are named") {
  Capabilities c;
  c.environmentLights = false;
  Requirements needs;
  needs.environmentLight = needs.heterogeneousMedium = true;
  const auto missing = unmet(c, needs);
  REQUIRE(missing.size() == 2);
  CHECK(missing[0] == "an environment light");
  CHECK(unmet(Capabilities{}, Requirements{}).empty());
}

TEST_CASE(
    "Outside its range, a technique names only the techniques that can also take the scene "
    "(a scan's density field), not every one whose range holds") {
  const auto technique = [](const char* name, bool heterogeneous, bool inRange) {
    Technique t;
    t.name = name;
    t.capabilities.heterogeneousMedia = heterogeneous;
    t.validity = [inRange](const SceneDescription&, const KnobValues&) {
      return std::string(inRange ? "" : "the object is too small");
    };
    return t;
  };
  Registry r;
  r.add(technique("narrow", true, false));
  r.add(technique("uniform-only", false, true));
  r.add(technique("any", true, true));
  SceneDescription scene;
  scene.medium.density = [](const glm::dvec3&) { return 0.5; };
  const ShadeRequest request;
  const Technique& narrow = r.get("narrow");
  CHECK_THROWS_WITH_AS(r.checkRange(narrow, scene, narrow.values(), &request),
                       doctest::Contains("with their defaults: any)"), RequestError);
  CHECK_THROWS_WITH_AS(r.checkRange(narrow, scene, narrow.values()),
                       doctest::Contains("defaults: uniform-only, any)"), RequestError);
}
