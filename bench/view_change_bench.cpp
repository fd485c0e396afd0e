// What a frame costs when only the view changes, against when the light changes, for the
// techniques that keep their light stages (technique/lit_stages.hpp), on lucent's default scene
// (or any scene `lucent render` takes). One prepare, then frames alternating a camera turned by a
// few degrees (the view: the stages are kept) with a light turned by a few degrees (everything a
// frame builds is built again, which is what every frame cost before the stages were kept). Both
// kinds are timed in the same run; the ratio is the speed-up of a view change. Each kind's phases
// (Statistics::frameSeconds) are printed as medians, so a frame's cost splits into its stages.
//
//   build/bench/view_change_bench [--method NAME]... [--knob NAME=VALUE]... [--frames N]
//       [scene options of lucent render: --shape, --size-mm, --material, --light, --width, ...]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <lucent/technique/registry.hpp>

#include "technique/core_registry.hpp"

#include "cli/args.hpp"
#include "cli/scene_setup.hpp"
#include "cli/technique_run.hpp"
#include "median.hpp"
#include "util/error.hpp"

namespace {
using lucent::bench::median;
namespace lt = lucent::technique;
using lucent::cli::Args;

/// The camera turned about its target's vertical axis by `degrees`.
lucent::scene::PinholeCamera turned(const lucent::scene::PinholeCamera& c, double degrees) {
  const double a = degrees * lucent::optics::kPi / 180, ca = std::cos(a), sa = std::sin(a);
  lucent::scene::PinholeCamera out = c;
  const glm::dvec3 d = c.eye - c.target;
  out.eye = c.target + glm::dvec3(ca * d.x + sa * d.z, d.y, -sa * d.x + ca * d.z);
  return out;
}

/// Every light turned about the vertical axis by `degrees` (a point light about the origin).
std::vector<lucent::scene::Light> turnedLights(std::vector<lucent::scene::Light> lights,
                                               double degrees) {
  const double a = degrees * lucent::optics::kPi / 180, ca = std::cos(a), sa = std::sin(a);
  const auto turn = [&](glm::dvec3 v) {
    return glm::dvec3(ca * v.x + sa * v.z, v.y, -sa * v.x + ca * v.z);
  };
  for (auto& light : lights) {
    if (auto* p = std::get_if<lucent::scene::PointLight>(&light)) p->position = turn(p->position);
    if (auto* d = std::get_if<lucent::scene::DirectionalLight>(&light))
      d->towardLight = turn(d->towardLight);
  }
  return lights;
}

/// One frame: its seconds, whether it reused the kept stages, and its phases' seconds.
struct TimedFrame {
  double seconds = 0;
  bool reused = false;
  std::vector<std::pair<std::string, double>> phases;
};

TimedFrame timeFrame(lt::Prepared& prepared, const lt::SceneDescription& scene,
                     const lt::ShadeRequest& request) {
  lt::Statistics stats;
  const lt::Stopwatch clock;
  lt::Registry::frame(prepared, scene, request, stats);
  const double s = clock.seconds();
  const auto reused = stats.figures.find("light_stages_reused");
  return {s, reused != stats.figures.end() && reused->second == 1, stats.frameSeconds};
}

/// "phase median ..." over frames whose phases come in the same order (a technique's frames do).
std::string phaseMedians(const std::vector<TimedFrame>& frames) {
  std::string out;
  for (std::size_t p = 0; !frames.empty() && p < frames.front().phases.size(); ++p) {
    std::vector<double> v;
    for (const TimedFrame& f : frames)
      if (p < f.phases.size()) v.push_back(f.phases[p].second);
    char figure[96];
    std::snprintf(figure, sizeof figure, " %s %.4f", frames.front().phases[p].first.c_str(),
                  median(v));
    out += figure;
  }
  return out;
}

void benchOne(const lt::Registry& registry, const lt::Technique& t, lucent::cli::Scene& scene,
              const lt::KnobList& knobs, int frames) {
  const lt::KnobValues values = t.values(knobs);
  const lt::ShadeRequest request = lt::pixelRequest(scene.camera, scene);
  lt::Statistics stats;
  const auto prepared = registry.prepare(t, scene, values, request, stats);
  const std::vector<lucent::scene::Light> lights = scene.lights;
  std::vector<TimedFrame> view, light;
  timeFrame(*prepared, scene, request);  // the first frame builds the stages
  for (int f = 1; f <= frames; ++f) {
    const lucent::scene::PinholeCamera camera = turned(scene.camera, 3.0 * f);
    const lt::ShadeRequest moved = lt::pixelRequest(camera, scene);
    view.push_back(timeFrame(*prepared, scene, moved));
    scene.lights = turnedLights(lights, 3.0 * f);
    light.push_back(timeFrame(*prepared, scene, moved));
  }
  scene.lights = lights;
  const auto seconds = [](const std::vector<TimedFrame>& frames) {
    std::vector<double> v;
    for (const TimedFrame& f : frames) v.push_back(f.seconds);
    return median(v);
  };
  const double v = seconds(view), l = seconds(light);
  const int reusedViews =
      int(std::count_if(view.begin(), view.end(), [](const TimedFrame& f) { return f.reused; }));
  std::printf("%-10s %8zu %14.4f %14.4f %10.1f %8d/%d\n", t.name.c_str(), request.points.size(), v,
              l, l / v, reusedViews, frames);
  std::printf("  phases (median s), view change:%s\n", phaseMedians(view).c_str());
  std::printf("  phases (median s), light change:%s\n", phaseMedians(light).c_str());
}
}  // namespace

int main(int argc, char** argv) {
  try {
    std::vector<lucent::cli::OptionSpec> specs = lucent::cli::sceneOptionSpecs();
    specs.push_back({"method", "NAME",
                     "a technique to time (repeatable; default: every technique that keeps its "
                     "light stages; one that does not, e.g. a baseline, builds every frame)",
                     true});
    specs.push_back({"knob", "NAME=VALUE", "a knob of every method timed (repeatable)", true});
    specs.push_back({"frames", "N", "view changes and light changes each (default 5)"});
    Args args("view_change_bench", "view_change_bench [options]", specs);
    args.parse(argc, argv, 1);
    if (args.helpRequested()) {
      std::printf("%s", args.helpText().c_str());
      return 0;
    }
    lucent::cli::Scene scene = lucent::cli::buildScene(args);
    const lt::Registry registry = lt::compiledCoreRegistry();
    std::vector<std::string> methods = args.all("method");
    if (methods.empty())
      for (const lt::Technique& t : registry.all())
        if (t.capabilities.keepsLightStages) methods.push_back(t.name);
    const double frameCount = lucent::cli::parseNumber(args.get("frames", "5"), "--frames");
    if (frameCount < 1 || frameCount > 1000)
      throw std::invalid_argument("--frames " + args.get("frames") + ": give 1 to 1000 frames");
    const int frames = int(frameCount);
    const lt::KnobList knobs = lucent::cli::knobArgs(args, "knob");
    std::printf("%-10s %8s %14s %14s %10s %9s\n", "technique", "points", "view change s",
                "light change s", "ratio", "reused");
    for (const std::string& name : methods) {
      const lt::Technique& t = registry.get(name);
      lt::KnobList own;
      for (const auto& [k, v] : knobs)
        if (t.knob(k)) own.emplace_back(k, v);
      benchOne(registry, t, scene, own, frames);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "view_change_bench: %s\n", e.what());
    return 2;
  }
  return 0;
}
