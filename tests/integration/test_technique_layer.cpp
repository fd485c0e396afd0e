// The technique layer as the front ends meet it: a technique registered by a test alone (no other
// edit) shows up in `lucent techniques --json`, runs through `render --method` and `bench`, and is
// refused before any work where its capabilities do not reach; the same check holds for the
// built-in techniques.
#include <doctest/doctest.h>

#include <map>
#include <tuple>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include <lucent/image/metrics.hpp>
#include <lucent/optics/profile.hpp>
#include <lucent/scene/shapes.hpp>

#include "cli/commands.hpp"
#include "io/exr_io.hpp"
#include "raycast/embree_ray_caster.hpp"
#include "technique/techniques.hpp"
#include "cli_run.hpp"
#include "temp_dir.hpp"

namespace {
using namespace lucent;
namespace lt = lucent::technique;
using lucent::test::contains;

/// Radiance = `level` everywhere: what a front end shows can be checked exactly.
technique::Technique constantTechnique() {
  technique::Technique t;
  t.name = "test-constant";
  t.summary = "test only: constant radiance";
  t.paper = "none";
  t.knobs = {
      technique::KnobSpec::real("level", "0.5", 0, 1, "", "the radiance returned"),
      technique::KnobSpec::choice("mode", {"plain", "doubled"}, "doubled returns 2 x level")};
  t.capabilities.environmentLights = false;
  t.defaultSweep = {{"level", {"0.25", "0.5"}}};
  struct Constant final : technique::Prepared {
    double value;
    explicit Constant(double v) : value(v) {}
    technique::FrameResult frame(const technique::SceneDescription&,
                                 const technique::ShadeRequest& request,
                                 technique::Statistics& stats) override {
      stats.frameSeconds.emplace_back("constant", 0.0);
      stats.samples = double(request.points.size());
      stats.sampleUnit = "points";
      technique::FrameResult out;
      out.radiance.assign(request.points.size(), glm::dvec3(value));
      return out;
    }
  };
  t.prepare = [](const technique::SceneDescription&, const technique::KnobValues& knobs,
                 technique::Statistics&) {
    const double scale = knobs.pick<double>("mode", {{"plain", 1.0}, {"doubled", 2.0}});
    return std::make_unique<Constant>(scale * knobs.real("level"));
  };
  return t;
}

void registerConstant() {
  if (!technique::appRegistry().find("test-constant"))
    technique::appRegistry().add(constantTechnique());
}

struct CliRun {
  int code = -1;
  std::string out, err;
};

using lucent::test::slurp;

/// Runs the CLI in this process (so it sees the test's registry), capturing stdout and stderr.
CliRun runCli(const std::vector<std::string>& words, const test::TempDir& dir) {
  std::vector<std::string> argvText{"lucent"};
  argvText.insert(argvText.end(), words.begin(), words.end());
  std::vector<char*> argv;
  for (auto& w : argvText) argv.push_back(w.data());
  const std::string outPath = dir / "cli-out.txt", errPath = dir / "cli-err.txt";
  std::fflush(stdout), std::fflush(stderr);
  std::cout.flush();
  const int savedOut = dup(1), savedErr = dup(2);
  REQUIRE(std::freopen(outPath.c_str(), "w", stdout));
  REQUIRE(std::freopen(errPath.c_str(), "w", stderr));
  CliRun r;
  r.code = lucent::cli::run(int(argv.size()), argv.data());
  std::cout.flush();
  std::fflush(stdout), std::fflush(stderr);
  dup2(savedOut, 1), dup2(savedErr, 2);
  close(savedOut), close(savedErr);
  r.out = slurp(outPath);
  r.err = slurp(errPath);
  return r;
}

}  // namespace

TEST_CASE(
    "A test-only technique reaches `techniques --json`, `render --method` and `bench` with no "
    "other edit") {
  registerConstant();
  test::TempDir dir;
  const CliRun list = runCli({"techniques", "--json"}, dir);
  REQUIRE(list.code == 0);
  CHECK(contains(list.out, "\"name\": \"test-constant\""));
  CHECK(contains(list.out, "\"vtk_name\": \"TestConstant\""));
  CHECK(contains(list.out, "\"choices\": [\"plain\", \"doubled\"]"));
  CHECK(contains(list.out, "\"environment_lights\": false"));

  const std::string exr = dir / "c.exr";
  const CliRun render =
      runCli({"render", "--shape", "sphere", "--width", "16", "--height", "16", "--quiet",
              "--method", "test-constant", "--knob", "level=0.25,mode=doubled", "--out", exr},
             dir);
  INFO(render.err);
  REQUIRE(render.code == 0);
  const image::Image img = io::readExr(exr);
  std::size_t covered = 0;
  for (std::size_t i = 0; i < img.pixels.size(); ++i)
    if (img.covered(i)) {
      ++covered;
      CHECK(img.pixels[i].g == doctest::Approx(0.5));
    } else {
      CHECK(img.pixels[i].g == 0);
    }
  CHECK(covered > 50);

  const std::string csv = dir / "b.csv";
  const CliRun bench = runCli(
      {"bench", "--shape", "sphere", "--size-mm", "5", "--width", "12", "--height", "12", "--quiet",
       "--method", "test-constant", "--reference-knob", "fraction=1", "--csv", csv},
      dir);
  INFO(bench.err);
  REQUIRE(bench.code == 0);
  const std::string table = slurp(csv);
  CHECK(contains(table, "test-constant,\"level=0.25;mode=plain\""));  // its own default sweep
  CHECK(contains(table, "test-constant,\"level=0.5;mode=plain\""));
  CHECK(contains(table, "\"points\""));  // typed statistics: its sample unit

  const CliRun badKnob = runCli(
      {"render", "--method", "test-constant", "--knob", "level=2", "--out", dir / "x.exr"}, dir);
  CHECK(badKnob.code == 2);
  CHECK(contains(badKnob.err, "knob level must be in [0, 1], not 2"));
}

TEST_CASE("A capability mismatch exits 2 before any work, naming the techniques that can") {
  registerConstant();
  test::TempDir dir;
  const std::string out = dir / "x.exr";
  struct Case {
    std::vector<std::string> args;
    std::string expect, notExpected;
  };
  const std::vector<Case> cases = {
      {{"--method", "hybrid", "--light", "env:uniform"},
       "cannot take an environment light; techniques that can: reference, jensen-buhler, tsis, "
       "diffuse-brdf, pathtrace",
       "hybrid,"},
      {{"--method", "tsm", "--light", "env:uniform"}, "cannot take an environment light", "tsm,"},
      {{"--method", "test-constant", "--light", "env:uniform"},
       "techniques that can: reference",
       "test-constant,"},
      {{"--method", "tsis", "--density", "noise:2"},
       "cannot take a heterogeneous medium (density field); techniques that can: taulut, "
       "voxel-single, pathtrace",
       "tsis,"},
      {{"--method", "reference", "--inclusion", "ketchup"},
       "cannot take an inclusion of another material; techniques that can: taulut, voxel-single, "
       "pathtrace",
       "jensen-buhler"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args{"render",   "--shape", "sphere",  "--width", "8",
                                  "--height", "8",       "--quiet", "--out",   out};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const CliRun r = runCli(args, dir);
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK(contains(r.err, c.expect));
    CHECK_FALSE(contains(r.err, c.notExpected));
    CHECK_FALSE(std::filesystem::exists(out));
  }
}

namespace {
/// A 10 mm sphere of `material` under `lights`, shaded at its vertices (no camera).
struct VertexScene {
  lt::SceneDescription scene;
  std::unique_ptr<raycast::EmbreeRayCaster> caster;
  VertexScene(const char* material, std::vector<scene::Light> lights) {
    scene.mesh = scene::shapes::sphere(5.0, 3);
    scene.vertexNormals = scene.mesh.vertexNormals();
    scene.medium.material = *optics::findMaterial(material);
    scene.lights = std::move(lights);
    caster = std::make_unique<raycast::EmbreeRayCaster>(scene.mesh);
    scene.caster = caster.get();
    scene.makeRayCaster = [](const scene::TriangleMesh& m) {
      return std::make_unique<raycast::EmbreeRayCaster>(m);
    };
  }
};

std::vector<glm::dvec3> frameOf(lt::Prepared& prepared, const VertexScene& s) {
  lt::Statistics stats;
  lt::FrameResult f = prepared.frame(s.scene, lt::vertexRequest(s.scene.mesh), stats);
  lt::completeRadiance(f, lt::vertexRequest(s.scene.mesh), s.scene.medium.material.eta);
  return f.radiance;
}

/// `light` as a technique can take it: itself, or, for a technique that takes only environments,
/// a sky whose radiance is the light's irradiance spread over the texels facing it (brighter
/// towards it, so a change of direction still moves the shading).
std::vector<scene::Light> lightsFor(const lt::Technique& t, const scene::DirectionalLight& light) {
  if (t.capabilities.directionalLights) return {light};
  scene::EnvironmentLight sky;
  sky.width = 32, sky.height = 16;
  const glm::dvec3 toward = glm::normalize(light.towardLight);
  for (int row = 0; row < sky.height; ++row)
    for (int col = 0; col < sky.width; ++col) {
      const double theta = optics::kPi * (row + 0.5) / sky.height;
      const double phi = 2 * optics::kPi * (col + 0.5) / sky.width;
      const glm::dvec3 d(std::sin(theta) * std::sin(phi), std::cos(theta),
                         -std::sin(theta) * std::cos(phi));
      sky.radiance.push_back(
          glm::vec3(light.irradiance * std::max(0.0, glm::dot(d, toward)) / optics::kPi));
    }
  return {sky};
}

}  // namespace

TEST_CASE(
    "Prepare once, change the light (and the material where declared dynamic): a frame equals a "
    "fresh run") {
  const scene::DirectionalLight firstLight{glm::dvec3(0, 0, 1), glm::dvec3(1)};
  const scene::DirectionalLight secondLight{glm::normalize(glm::dvec3(1, 0.5, 0.2)), glm::dvec3(2)};
  for (const auto& t : lt::appRegistry().all()) {
    if (t.capabilities.needsCamera || t.name.rfind("test-", 0) == 0) continue;
    INFO(t.name);
    const std::vector<scene::Light> first = lightsFor(t, firstLight);
    const std::vector<scene::Light> second = lightsFor(t, secondLight);
    const lt::KnobValues knobs = t.values(t.quickKnobs);  // reuse is exact at any accuracy
    VertexScene built("skin1", first);
    lt::Statistics stats;
    const std::unique_ptr<lt::Prepared> prepared = t.prepare(built.scene, knobs, stats);
    CHECK_FALSE(frameOf(*prepared, built).empty());

    VertexScene moved("skin1", second);
    REQUIRE(t.capabilities.dynamicLight);
    const auto reused = frameOf(*prepared, moved);
    const auto fresh = frameOf(*t.prepare(moved.scene, knobs, stats), moved);
    CHECK(image::relativeRms(reused, fresh) < 1e-9);

    VertexScene marble("marble", second);
    const auto reusedMaterial = frameOf(*prepared, marble);
    const double materialDifference =
        image::relativeRms(reusedMaterial, frameOf(*t.prepare(marble.scene, knobs, stats), marble));
    if (t.capabilities.dynamicMaterial)
      CHECK(materialDifference < 1e-9);
    else
      MESSAGE(t.name << ": a material change without a new prepare differs by "
                     << materialDifference << " (declared static)");
  }
}

namespace {
/// Another valid value of knob `k` than `current` (a choice's next, a number halved or moved into
/// its range), or empty when the knob has no other (text, files).
std::string otherValue(const lt::KnobSpec& k, const std::string& current, const lt::Technique& t) {
  std::vector<std::string> candidates;
  if (k.kind == lt::KnobKind::Choice) {
    const auto at = std::find(k.choices.begin(), k.choices.end(), current);
    if (at != k.choices.end() && k.choices.size() > 1)
      candidates.push_back(std::next(at) == k.choices.end() ? k.choices.front() : *std::next(at));
  } else if (k.kind == lt::KnobKind::Integer || k.kind == lt::KnobKind::Real) {
    const double v = std::stod(current);
    const double lo = std::isfinite(k.min) ? k.min : -1e3, hi = std::isfinite(k.max) ? k.max : 1e3;
    for (const double c : {v / 2, v + 1, v - 1, lo + (hi - lo) / 4})
      candidates.push_back(k.kind == lt::KnobKind::Integer ? std::to_string(std::llround(c))
                                                           : std::to_string(c));
  }
  for (const auto& c : candidates) {
    if (c == current || (k.kind != lt::KnobKind::Choice && std::stod(c) == std::stod(current)))
      continue;
    try {
      (void)t.values({{k.name, c}});
      return c;
    } catch (const std::exception&) {
    }
  }
  return {};
}
}  // namespace

TEST_CASE(
    "Prepare once, change every frame-phase knob: the retuned frame equals a fresh run (no knob "
    "that claims to invalidate only the frame is read at prepare)") {
  // Every technique's own list: a new technique or knob is checked here with no edit.
  const scene::DirectionalLight light{glm::normalize(glm::dvec3(1, 0.5, 0.2)), glm::dvec3(1)};
  for (const auto& t : lt::appRegistry().all()) {
    if (t.capabilities.needsCamera || t.name.rfind("test-", 0) == 0) continue;
    INFO(t.name);
    const VertexScene s("skin1", lightsFor(t, light));
    const lt::KnobValues before = t.values(t.quickKnobs);
    lt::KnobList changed = t.quickKnobs;
    std::string what;
    for (const auto& k : t.knobs)
      if (k.invalidates == lt::Phase::Frame)
        if (const std::string v = otherValue(k, before.text(k.name), t); !v.empty()) {
          changed.emplace_back(k.name, v);
          what += " " + k.name + "=" + v;
        }
    INFO("changed:" << what);
    const lt::KnobValues after = t.values(changed);
    lt::Statistics stats;
    const std::unique_ptr<lt::Prepared> prepared = t.prepare(s.scene, before, stats);
    const auto original = frameOf(*prepared, s);
    prepared->retune(after);
    std::vector<glm::dvec3> retuned, fresh;
    std::string refusedFresh, refusedRetuned;  // a value a frame refuses is refused both ways
    try {
      fresh = frameOf(*t.prepare(s.scene, after, stats), s);
    } catch (const lt::RequestError& e) {
      refusedFresh = e.what();
    }
    try {
      retuned = frameOf(*prepared, s);
    } catch (const lt::RequestError& e) {
      refusedRetuned = e.what();
    }
    CHECK(refusedRetuned == refusedFresh);
    if (!refusedFresh.empty()) {
      MESSAGE(t.name << ": changing" << what << " is refused: " << refusedFresh);
      continue;
    }
    CHECK(image::relativeRms(retuned, fresh) < 1e-9);
    MESSAGE(t.name << ": changing" << what << " moved the frame by "
                   << image::relativeRms(retuned, original));
  }
}

TEST_CASE(
    "Every technique that takes a profile renders every profile: finite, and the profile moves its "
    "radiance as it moves the reference's") {
  // The techniques and the profiles are the registry's and the core's own lists; a new technique
  // with a `profile` knob is checked here with no edit. Per channel, each technique's summed vertex
  // radiance with profile M over its own with the classic dipole must match the reference's ratio.
  const scene::DirectionalLight light{glm::normalize(glm::dvec3(1, 0.5, 0.2)), glm::dvec3(1)};
  // Summed vertex radiance of (technique, profile, kind of light), each computed once.
  std::map<std::tuple<std::string, std::string, bool>, glm::dvec3> sums;
  const auto summed = [&](const lt::Technique& t, const std::string& model,
                          const lt::Technique& lightsOf) {
    const auto key = std::make_tuple(t.name, model, lightsOf.capabilities.directionalLights);
    if (const auto it = sums.find(key); it != sums.end()) return it->second;
    const VertexScene s("skin1", lightsFor(lightsOf, light));
    lt::Statistics stats;
    // The profile is the multiple-scattering term's: an added single-scattering term is left out.
    lt::KnobList knobs = {{"profile", model}};
    if (t.knob("single")) knobs.emplace_back("single", "off");
    const auto prepared = t.prepare(s.scene, t.values(knobs), stats);
    glm::dvec3 sum(0);
    for (const auto& v : frameOf(*prepared, s)) {
      REQUIRE((std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)));
      CHECK((v.x >= 0 && v.y >= 0 && v.z >= 0));
      sum += v;
    }
    return sums[key] = sum;
  };
  const lt::Technique& reference = *lt::appRegistry().find("reference");
  int checked = 0;
  for (const auto& info : optics::kProfileModels) {
    const std::string model(info.name);
    for (const auto& t : lt::appRegistry().all()) {
      if (!t.knob("profile") || t.capabilities.needsCamera || t.name == "reference") continue;
      // The reference under the same light as the technique.
      const glm::dvec3 referenceRatio =
          summed(reference, model, t) / summed(reference, "dipole", t);
      const glm::dvec3 ratio = summed(t, model, t) / summed(t, "dipole", t);
      for (int c = 0; c < 3; ++c) {
        INFO(t.name << " profile " << model << " channel " << c << ": " << ratio[c]
                    << " against the reference's " << referenceRatio[c]);
        CHECK(ratio[c] == doctest::Approx(referenceRatio[c]).epsilon(0.03));
      }
      ++checked;
    }
  }
  CHECK(checked >= 4 * int(optics::kProfileModels.size()));  // jensen-buhler, tsis, hybrid, tsm
}

namespace {
void writeObj(const std::string& path, const scene::TriangleMesh& m) {
  std::ofstream f(path);
  for (const auto& p : m.positions) f << "v " << p.x << " " << p.y << " " << p.z << "\n";
  for (const auto& t : m.triangles)
    f << "f " << t.x + 1 << " " << t.y + 1 << " " << t.z + 1 << "\n";
}
}  // namespace

TEST_CASE(
    "Inner bodies from the CLI: --inclusion-mesh in the object's coordinates, --fill for the "
    "bottle, bad ones exit 2 with the fix") {
  test::TempDir dir;
  const std::string body = dir / "body.obj", core = dir / "core.obj", outside = dir / "out.obj";
  writeObj(body, scene::shapes::sphere(10.0, 3));
  writeObj(core, scene::shapes::sphere(4.0, 3, glm::dvec3(2, 0, 0)));
  writeObj(outside, scene::shapes::sphere(4.0, 3, glm::dvec3(9, 0, 0)));
  const std::string out = dir / "o.png";
  const std::vector<std::string> base{"render",   "--width",      "8",      "--height",
                                      "8",        "--quiet",      "--out",  out,
                                      "--method", "voxel-single", "--knob", "voxels=12"};
  auto run = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = base;
    args.insert(args.end(), extra.begin(), extra.end());
    return runCli(args, dir);
  };
  CliRun r = run({"--mesh", body, "--inclusion-mesh", core + ":Ketchup"});
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK(contains(r.err, "Ketchup body from " + core));
  r = run({"--mesh", body, "--inclusion-mesh", outside + ":Ketchup"});
  CHECK(r.code == 2);
  CHECK(contains(r.err, "is not inside the object"));
  r = run({"--mesh", body, "--inclusion-mesh", core + ":Jelly"});
  CHECK(r.code == 2);
  CHECK(contains(r.err, "'Jelly' is not a material"));
  r = run({"--shape", "sphere", "--inclusion-mesh", core + ":Ketchup"});
  CHECK(r.code == 2);
  CHECK(contains(r.err, "--inclusion-mesh needs --mesh"));
  writeObj(dir / "big.obj", scene::shapes::sphere(6.0, 3));
  r = run({"--mesh", body, "--inclusion-mesh", core + ":Ketchup", "--inclusion-mesh",
           dir / "big.obj" + ":Marble"});
  CHECK(r.code == 2);
  CHECK(contains(r.err, "overlaps Ketchup body"));
  r = run({"--mesh", body, "--inclusion-mesh", dir / "missing.obj" + ":Ketchup"});
  CHECK(r.code == 2);
  CHECK(contains(r.err, "--inclusion-mesh: "));
  r = run({"--mesh", body, "--fill", "Merlot"});
  CHECK(r.code == 2);
  CHECK(contains(r.err, "give the body as --inclusion-mesh"));
  r = run({"--shape", "sphere", "--fill", "Merlot"});
  CHECK(r.code == 2);
  CHECK(contains(r.err, "has no inner body"));
  r = run({"--shape", "bottle", "--fill", "Cranberry Juice"});
  CHECK(r.code == 0);
  CHECK(contains(r.err, "Cranberry Juice as the liquid"));
}
