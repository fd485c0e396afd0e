// Relighting a translucent object under a turning environment with wavelet PRT (Wang, Tran, Luebke
// 2005): the transport vectors are precomputed once; each frame only turns the environment, takes
// its Haar transform and the largest terms, and does the sparse dot products.
//
//   build/examples/prt_relight [ENV.exr] [OUT_DIR]   (default: a synthetic sky with a sun;
//   prt-relight)
// prints the precomputation's stages and the time of each frame, and writes OUT_DIR/frames.png (the
// environment turned by 0, 45, ..., 315 degrees about +y) and OUT_DIR/sky.exr (the environment).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <lucent/image/image.hpp>

#include "cli/image_output.hpp"
#include "cli/scene_setup.hpp"
#include "io/exr_io.hpp"
#include "scene/synthetic_sky.hpp"
#include "technique/techniques.hpp"
#include "util/error.hpp"

using namespace lucent;

namespace {
/// The environment turned about +y by a whole number of lat-long columns (exact).
scene::EnvironmentLight turned(const scene::EnvironmentLight& env, int columns) {
  scene::EnvironmentLight out = env;
  for (int row = 0; row < env.height; ++row)
    for (int col = 0; col < env.width; ++col)
      out.radiance[std::size_t(row) * env.width + (col + columns) % env.width] =
          env.radiance[std::size_t(row) * env.width + col];
  return out;
}

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}
}  // namespace

int main(int argc, char** argv) try {
  const std::string envPath = argc > 1 && std::string(argv[1]) != "-" ? argv[1] : "";
  const std::filesystem::path outDir = argc > 2 ? argv[2] : "prt-relight";
  std::filesystem::create_directories(outDir);

  // The scene as `lucent render --shape torus --light env:...` builds it.
  cli::Args args("example", "", cli::sceneOptionSpecs());
  std::vector<std::string> words = {
      "example", "--shape", "torus",
      "--width", "160",     "--height",
      "160",     "--light", envPath.empty() ? "env:uniform" : "env:" + envPath};
  std::vector<char*> argvScene;
  for (auto& w : words) argvScene.push_back(w.data());
  args.parse(int(argvScene.size()), argvScene.data(), 1);
  cli::Scene scene = cli::buildScene(args);
  const scene::EnvironmentLight sky = envPath.empty()
                                          ? scene::syntheticSky()
                                          : std::get<scene::EnvironmentLight>(scene.lights.front());

  const technique::Technique& prt = technique::appRegistry().get("prt");
  technique::KnobList given;
  for (int i = 3; i < argc; ++i) {
    const std::string knob = argv[i];
    const auto eq = knob.find('=');
    if (eq == std::string::npos) throw InputError("knob '" + knob + "': write NAME=VALUE");
    given.emplace_back(knob.substr(0, eq), knob.substr(eq + 1));
  }
  const technique::KnobValues knobs = prt.values(given);
  const technique::ShadeRequest request = technique::pixelRequest(scene.camera, scene);
  scene.lights = {sky};
  technique::Statistics stats;
  auto t = std::chrono::steady_clock::now();
  std::unique_ptr<technique::Prepared> prepared = prt.prepare(scene, knobs, stats);
  std::printf("precomputed once in %.2f s (%zu vertices, %.1f MB of transport vectors):\n",
              since(t), scene.mesh.positions.size(), stats.bytes / 1e6);
  for (const auto& [phase, seconds] : stats.prepareSeconds)
    std::printf("  %-22s %.2f s\n", phase.c_str(), seconds);

  std::vector<image::Image> frames;
  std::printf("%8s %10s\n", "turn", "frame ms");
  for (int step = 0; step < 8; ++step) {
    scene.lights = {turned(sky, step * sky.width / 8)};
    technique::Statistics frameStats;
    t = std::chrono::steady_clock::now();
    technique::FrameResult frame = prepared->frame(scene, request, frameStats);
    std::printf("%7d° %10.1f\n", step * 45, 1e3 * since(t));
    image::Image img(scene.camera.width, scene.camera.height);
    for (std::size_t i = 0; i < request.points.size(); ++i)
      img.pixels[request.pixels[i]] = glm::vec4(glm::vec3(frame.radiance[i]), 1);
    frames.push_back(img);
  }
  const int w = frames[0].width, h = frames[0].height;
  image::Image sheet(4 * w, 2 * h);
  for (std::size_t f = 0; f < frames.size(); ++f)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        sheet.at(int(f % 4) * w + x, int(f / 4) * h + y) = frames[f].at(x, y);
  cli::writeImage((outDir / "frames.png").string(), sheet, image::ToneMap{});
  image::Image skyImage(sky.width, sky.height);
  for (std::size_t i = 0; i < sky.radiance.size(); ++i)
    skyImage.pixels[i] = glm::vec4(sky.radiance[i], 1);
  io::writeExr((outDir / "sky.exr").string(), skyImage);  // for `lucent render --light env:...`
  std::printf("wrote %s and %s\n", (outDir / "frames.png").c_str(), (outDir / "sky.exr").c_str());
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "prt_relight: %s\n", e.what());
  return 2;
}
