// What the atlas's irradiance costs with its shadow rays cast one at a time against cast as streams
// (RayCaster::occludedMany, Embree's rtcOccluded1M with the coherent flag), in the same run, on
// lucent's default scene (or any scene `lucent render` takes) with tsis's atlas. The stage is what
// a light change redoes for tsis and the hybrid (atlas::lightAtlas). Runs alternate between the
// two; the medians and their ratio are printed, and the two atlases are compared texel by texel.
//
//   build/bench/shadow_ray_bench [--runs N] [scene options of lucent render]
#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <lucent/technique/registry.hpp>

#include "technique/core_registry.hpp"
#include <lucent/technique/texture_space.hpp>

#include "cli/args.hpp"
#include "cli/scene_setup.hpp"
#include "median.hpp"

namespace {
using lucent::bench::median;
namespace lt = lucent::technique;
using lucent::scene::RayCaster;
}  // namespace

int main(int argc, char** argv) {
  try {
    std::vector<lucent::cli::OptionSpec> specs = lucent::cli::sceneOptionSpecs();
    specs.push_back({"runs", "N", "runs of each way (default 7)"});
    lucent::cli::Args args("shadow_ray_bench", "shadow_ray_bench [options]", specs);
    args.parse(argc, argv, 1);
    if (args.helpRequested()) {
      std::printf("%s", args.helpText().c_str());
      return 0;
    }
    const double runCount = lucent::cli::parseNumber(args.get("runs", "7"), "--runs");
    if (runCount < 1 || runCount > 1000)
      throw std::invalid_argument("--runs " + args.get("runs") + ": give 1 to 1000 runs");
    const lucent::cli::Scene scene = lucent::cli::buildScene(args);
    const lt::Registry registry = lt::compiledCoreRegistry();
    const lt::KnobValues knobs = registry.get("tsis").values({});
    lt::Statistics stats;
    const auto surface = lt::detail::buildAtlas(scene, knobs, stats);
    const auto settings = lt::detail::irradianceSettings(scene, knobs);
    const lucent::scene::OneRayAtATime single(*scene.caster);
    const auto light = [&](const RayCaster& caster) {
      const lt::Stopwatch clock;
      auto atlas =
          lucent::atlas::lightAtlas(surface, scene.lights, caster, settings, scene.parallelFor);
      return std::make_pair(clock.seconds(), std::move(atlas));
    };
    // One atlas alive at a time, as in a frame: two would make the allocator hand their 16 MB back
    // to the system each time, and the timings would be page faults (docs/performance.md).
    std::vector<double> one, streams;
    std::vector<glm::vec3> firstOne, firstStreams;  // run 0's atlases, compared texel by texel
    for (int run = 0; run < int(runCount); ++run) {
      {
        auto [seconds, atlas] = light(single);
        one.push_back(seconds);
        if (run == 0) firstOne = std::move(atlas.power);
      }
      auto [seconds, atlas] = light(*scene.caster);
      streams.push_back(seconds);
      if (run == 0) firstStreams = std::move(atlas.power);
    }
    std::size_t differing = 0;
    for (std::size_t i = 0; i < firstOne.size(); ++i) differing += firstOne[i] != firstStreams[i];
    const std::size_t rays = surface->owned.size() * scene.lights.size();
    const double t1 = median(one), t2 = median(streams);
    std::printf("atlas irradiance: %zu covered texels x %zu lights, %d runs each (medians)\n",
                surface->owned.size(), scene.lights.size(), int(runCount));
    std::printf("one ray at a time : %8.4f s  %6.2f M texel-lights/s\n", t1, rays / t1 * 1e-6);
    std::printf("ray streams       : %8.4f s  %6.2f M texel-lights/s\n", t2, rays / t2 * 1e-6);
    std::printf("speed-up          : %8.2fx; texels that differ: %zu of %zu\n", t1 / t2, differing,
                surface->owned.size());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadow_ray_bench: %s\n", e.what());
    return 2;
  }
  return 0;
}
