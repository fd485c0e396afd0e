#include "technique_run.hpp"

#include <algorithm>
#include <memory>
#include <mutex>

#include "../io/atomic_file.hpp"
#include "../io/exr_io.hpp"
#include "../render/knobs.hpp"
#include "../util/progress_bar.hpp"

namespace lucent::cli {

namespace {
/// One progress bar per stage, the current one replaced when a technique moves on to the next.
class StageBars {
 public:
  explicit StageBars(bool enabled) : mEnabled(enabled) {}
  void update(const std::string& stage, double fraction) {
    const std::lock_guard<std::mutex> lock(mMutex);
    if (stage != mStage) {
      if (mBar) mBar->finish();
      mBar = std::make_unique<util::ProgressBar>(stage, mEnabled);
      mStage = stage;
    }
    mBar->update(fraction);
  }
  void finish() {
    const std::lock_guard<std::mutex> lock(mMutex);
    if (mBar) mBar->finish();
    mBar.reset();
    mStage.clear();
  }

 private:
  bool mEnabled;
  std::mutex mMutex;
  std::string mStage;
  std::unique_ptr<util::ProgressBar> mBar;
};

image::Image toImage(const scene::PinholeCamera& camera, const technique::ShadeRequest& request,
                     const std::vector<glm::dvec3>& values) {
  image::Image img(camera.width, camera.height);
  for (std::size_t i = 0; i < request.pixels.size(); ++i)
    img.pixels[request.pixels[i]] = glm::vec4(glm::vec3(values[i]), 1.0f);
  return img;
}
}  // namespace

technique::KnobList knobArgs(const Args& args, const std::string& option) {
  technique::KnobList out;
  for (const auto& k : args.all(option))
    for (const auto& [name, value] : render::parseKnobList(k)) out.emplace_back(name, value);
  return out;
}

const technique::Technique& techniqueArg(const technique::Registry& registry, const Args& args,
                                         const std::string& option) {
  return args.has(option) ? registry.get(args.get(option)) : registry.defaultReference();
}

std::vector<technique::KnobValues> sweepSettings(const technique::Technique& t,
                                                 const technique::KnobList& fixed,
                                                 const std::vector<technique::Sweep>& sweeps) {
  std::vector<technique::KnobList> combos{fixed};
  for (const auto& [name, values] : sweeps) {
    std::vector<technique::KnobList> next;
    for (const auto& c : combos)
      for (const auto& v : values) {
        auto k = c;
        k.emplace_back(name, v);
        next.push_back(k);
      }
    combos.swap(next);
  }
  std::vector<technique::KnobValues> settings;
  for (const auto& c : combos) settings.push_back(t.values(c));
  return settings;
}

std::vector<NamedOutput> knobOutputs(const std::vector<technique::KnobValues>& settings) {
  std::vector<NamedOutput> out;
  for (const auto& knobs : settings)
    for (const auto& spec : knobs.specs()) {
      const NamedOutput o{"--knob " + spec.name, knobs.text(spec.name)};
      if (spec.kind != technique::KnobKind::OutputFile || o.path.empty()) continue;
      if (std::none_of(out.begin(), out.end(), [&](const NamedOutput& k) { return k.path == o.path; }))
        out.push_back(o);
    }
  return out;
}

ImageRun renderImage(const technique::Registry& registry, const technique::Technique& technique,
                     Scene& scene, const technique::KnobValues& knobs, bool progress,
                     const technique::ShadeRequest* pixels) {
  StageBars bars(progress);
  // --quiet: no callback at all, so techniques that draw their own stage bars (quadgraph) stay
  // silent too.
  if (progress)
    scene.progress = [&bars](const std::string& stage, double f) { bars.update(stage, f); };
  struct Unhook {  // the callback must not outlive the bars, on any way out
    Scene& scene;
    ~Unhook() { scene.progress = {}; }
  } unhook{scene};
  const technique::ShadeRequest request =
      pixels ? *pixels : technique::pixelRequest(scene.camera, scene);
  technique::Rendered r = registry.render(technique, scene, knobs, request);
  bars.finish();

  ImageRun out;
  out.image = toImage(scene.camera, request, r.frame.radiance);
  out.stats = std::move(r.stats);
  out.figures = out.stats.flat();
  out.figures["shaded_pixels"] = double(request.points.size());
  out.seconds = r.seconds;
  for (auto& [name, values] : r.frame.extras) {
    out.extras.emplace_back(name, toImage(scene.camera, request, values));
    const technique::KnobSpec* spec = technique.knob(name);
    if (spec && spec->kind == technique::KnobKind::OutputFile && !knobs.text(name).empty())
      io::writeExr(knobs.text(name), out.extras.back().second);
  }
  return out;
}

}  // namespace lucent::cli
