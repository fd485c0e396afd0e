/// `lucent report`: the accuracy-cost report of one scene. Runs every technique whose capabilities
/// fit the scene over its own sweep (or its quick setting), measures each setting against the
/// physical truth and against the truth of its own model, and writes DIR/index.html: the Pareto
/// front of error against time, a table per setting, the images and their error maps. Results are
/// cached per setting in DIR/cache, so a run cut short resumes. It names no technique: the list,
/// the sweeps and the truths come from the registry.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

#include <lucent/image/metrics.hpp>
#include <lucent/technique/pareto.hpp>

#include "../io/atomic_file.hpp"
#include "../io/png_io.hpp"
#include "../plot/line_chart.hpp"
#include "../report/error_map.hpp"
#include "../report/report_cache.hpp"
#include "../report/report_page.hpp"
#include "../technique/techniques.hpp"
#include "../util/error.hpp"
#include "commands.hpp"
#include "technique_run.hpp"

namespace lucent::cli {

namespace {
namespace lt = lucent::technique;
namespace rp = lucent::report;

struct Options {
  std::string out;
  bool physical = true, model = true, quick = false, progress = true;
  double budgetSeconds = INFINITY, errorScale = 0.25;
};

/// One technique at one setting, to be measured (or a truth, to measure against).
struct Job {
  const lt::Technique* technique;
  lt::KnobValues knobs;
};

struct Measured {
  Job job;
  rp::SettingResult result;
  bool cached = false;
};

std::vector<OptionSpec> reportOptionSpecs() {
  std::vector<OptionSpec> specs = sceneOptionSpecs();
  specs.push_back({"out", "DIR", "folder of the report (index.html, pictures, cache); created"});
  specs.push_back({"truth", "both|physical|model",
                   "the truths to measure against: the physical one (radiative transfer), each "
                   "technique's own model's, or both (default)"});
  specs.push_back({"truth-knob", "TECHNIQUE.KNOB=VALUE",
                   "a knob of a truth instead of its converged setting (e.g. fewer samples)",
                   true});
  specs.push_back({"budget-s", "S",
                   "start no new setting after S seconds; run again to resume (default: none)"});
  specs.push_back({"quick", "", "each technique at its quick setting only, not its sweep"});
  specs.push_back({"error-scale", "X",
                   "relative error shown at the top of the error maps' ramp (default 0.25)"});
  specs.push_back({"quiet", "", "no progress bars"});
  return specs;
}

Options optionsOf(const Args& args) {
  Options o;
  if (!args.has("out")) args.fail("--out DIR is required: the folder the report is written to");
  o.out = args.get("out");
  const std::string truth = args.get("truth", "both");
  if (truth != "both" && truth != "physical" && truth != "model")
    args.fail("--truth must be both, physical or model, not '" + truth + "'");
  o.physical = truth != "model";
  o.model = truth != "physical";
  if (args.has("budget-s")) o.budgetSeconds = args.number("budget-s", 0, 0, 1e9);
  o.errorScale = args.number("error-scale", 0.25, 1e-6, 1e6);
  o.quick = args.has("quick");
  o.progress = !args.has("quiet");
  return o;
}

/// The scene's fingerprint: every scene option as given, the bytes of each file they name, and
/// the lucent executable (a rebuilt lucent measures again).
std::string sceneKey(const Args& args) {
  lucent::util::Fingerprint f;
  rp::addFile(f, "/proc/self/exe");
  for (const OptionSpec& spec : sceneOptionSpecs())
    for (const std::string& value : args.all(spec.name)) {
      f.add(spec.name).add(value);
      std::error_code ec;
      if (std::filesystem::is_regular_file(value, ec)) rp::addFile(f, value);
    }
  return f.hex();
}

/// A truth's converged setting, with the --truth-knob entries addressed to it.
lt::KnobValues truthKnobs(const lt::Registry& registry, const lt::Technique& truth,
                          const Args& args) {
  lt::KnobList knobs = truth.referenceKnobs;
  for (const auto& [name, value] : knobArgs(args, "truth-knob")) {
    const auto dot = name.find('.');
    const lt::Technique* named =
        dot == std::string::npos ? nullptr : registry.find(name.substr(0, dot));
    if (!named || !named->capabilities.groundTruth)
      args.fail("--truth-knob '" + name + "=" + value + "' must be TECHNIQUE.KNOB=VALUE for a " +
                "truth: " +
                registry.names([](const lt::Technique& t) { return t.capabilities.groundTruth; }));
    if (name.substr(0, dot) == truth.name) knobs.emplace_back(name.substr(dot + 1), value);
  }
  return truth.values(knobs);
}

/// The settings of every technique that fits the scene; those that do not, with the reason.
std::vector<Job> settingsToRun(const lt::Registry& registry, const Scene& scene,
                               const lt::ShadeRequest& request, const Options& o,
                               std::vector<rp::PageNote>& notRun) {
  std::vector<Job> jobs;
  for (const lt::Technique& t : registry.all()) {
    if (!o.physical && !registry.truthOf(t.model)) {  // nothing to measure it against
      notRun.push_back({t.name, "",
                        "its model (" + t.model +
                            ") has no truth of its own; --truth both measures it "
                            "against the physical truth"});
      continue;
    }
    const bool quick = o.quick;
    const std::vector<lt::KnobValues> settings =
        quick || t.defaultSweep.empty() ? std::vector<lt::KnobValues>{t.values(t.quickKnobs)}
                                        : sweepSettings(t, {}, t.defaultSweep);
    for (const lt::KnobValues& k : settings) {
      try {
        registry.check(t, scene, request);
        registry.checkRange(t, scene, k);
        jobs.push_back({&t, k});
      } catch (const lt::RequestError& e) {
        notRun.push_back({t.name, k.summary(true), e.what()});
        break;  // the capability or range fails for the technique, not for one setting
      }
    }
  }
  return jobs;
}

/// Runs the jobs (or reads them from the cache), in order, within the budget.
class Runner {
 public:
  Runner(const lt::Registry& registry, Scene& scene, const Options& options,
         const rp::ResultCache& cache)
      : mRegistry(registry), mScene(scene), mOptions(options), mCache(cache) {}

  std::optional<Measured> run(const Job& job, const std::string& label,
                              std::vector<rp::PageNote>& notRun) {
    const std::string knobs = job.knobs.summary();
    if (auto cached = mCache.load(job.technique->name, knobs, mScene.camera.width,
                                  mScene.camera.height))
      return Measured{job, *cached, true};
    if (elapsed() > mOptions.budgetSeconds) {
      notRun.push_back({job.technique->name, job.knobs.summary(true),
                        "over the budget (--budget-s); run the same command again to resume"});
      return std::nullopt;
    }
    std::fprintf(stderr, "lucent report: %s %s (%s)\n", label.c_str(), job.technique->name.c_str(),
                 job.knobs.summary(true).c_str());
    try {
      const ImageRun r =
          renderImage(mRegistry, *job.technique, mScene, job.knobs, mOptions.progress);
      rp::SettingResult s{job.technique->name,
                          knobs,
                          job.knobs.summary(true),
                          r.seconds,
                          r.stats.totalPrepareSeconds(),
                          r.stats.totalFrameSeconds(),
                          r.stats.samples,
                          r.stats.sampleUnit,
                          r.stats.bytes,
                          r.stats.warnings,
                          r.image};
      mCache.store(s);
      return Measured{job, std::move(s), false};
    } catch (const lt::RequestError& e) {
      notRun.push_back({job.technique->name, job.knobs.summary(true), e.what()});
      return std::nullopt;
    }
  }

 private:
  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - mStart).count();
  }
  const lt::Registry& mRegistry;
  Scene& mScene;
  const Options& mOptions;
  const rp::ResultCache& mCache;
  std::chrono::steady_clock::time_point mStart = std::chrono::steady_clock::now();
};

/// The truths the settings are measured against: the physical one and each model's, by model.
struct Truths {
  std::optional<Measured> physical;
  std::map<std::string, Measured> byModel;
  /// The truth a model is measured against (null: none).
  const Measured* ofModel(const std::string& model) const {
    const auto it = byModel.find(model);
    return it == byModel.end() ? nullptr : &it->second;
  }
};

Truths measureTruths(const lt::Registry& registry, const Args& args, const Options& o,
                     const std::vector<Job>& jobs, Runner& runner,
                     std::vector<rp::PageNote>& notRun) {
  Truths truths;
  if (o.physical && registry.physicalTruth()) {
    const lt::Technique& t = *registry.physicalTruth();
    truths.physical = runner.run({&t, truthKnobs(registry, t, args)}, "[physical truth]", notRun);
  }
  if (!o.model) return truths;
  for (const Job& j : jobs) {
    const std::string& model = j.technique->model;
    const lt::Technique* t = registry.truthOf(model);
    if (!t || truths.byModel.count(model)) continue;
    if (truths.physical && truths.physical->job.technique == t) {
      truths.byModel.emplace(model, *truths.physical);
      continue;
    }
    if (auto m =
            runner.run({t, truthKnobs(registry, *t, args)}, "[truth of " + model + "]", notRun))
      truths.byModel.emplace(model, std::move(*m));
  }
  return truths;
}

double errorAgainst(const Measured& m, const Measured* truth) {
  if (!truth) return std::nan("");
  return image::compareImages(m.result.image, truth->result.image).relativeRms;
}

/// The display tone map of every picture: the paper's, with the first truth's average radiance,
/// so that the pictures compare.
image::ToneMap sharedToneMap(const Truths& truths, const std::vector<Measured>& measured) {
  image::ToneMap t;
  const Measured* first = truths.physical           ? &*truths.physical
                          : !truths.byModel.empty() ? &truths.byModel.begin()->second
                          : measured.empty()        ? nullptr
                                                    : &measured.front();
  if (first) t.averageRadiance = image::meanCoveredLuminance(first->result.image);
  return t;
}

/// Writes DIR/img/<stem>.png and returns its relative path.
std::string writePicture(const Options& o, const std::string& stem, const image::Image& display) {
  const std::string relative = "img/" + stem + ".png";
  io::writePng(o.out + "/" + relative, display);
  return relative;
}

void markFronts(std::vector<rp::PageRow>& rows) {
  std::vector<lt::CostPoint> model, physical;
  for (const auto& r : rows) {
    model.push_back({r.seconds, r.modelError});
    physical.push_back({r.seconds, r.physicalError});
  }
  for (std::size_t i : lt::paretoFront(model)) rows[i].onModelFront = true;
  for (std::size_t i : lt::paretoFront(physical)) rows[i].onPhysicalFront = true;
}

rp::PageRow pageRow(const Options& o, const rp::ResultCache& cache, const Measured& m,
                    const Truths& truths, const image::ToneMap& toneMap) {
  const Measured* modelTruth = truths.ofModel(m.job.technique->model);
  const Measured* physical = truths.physical ? &*truths.physical : nullptr;
  const rp::SettingResult& s = m.result;
  const std::string stem = cache.stem(s.technique, s.knobs);
  rp::PageRow r;
  r.technique = s.technique, r.model = m.job.technique->model, r.knobs = s.changedKnobs;
  r.seconds = s.seconds, r.prepareSeconds = s.prepareSeconds, r.frameSeconds = s.frameSeconds;
  r.samples = s.samples, r.sampleUnit = s.sampleUnit, r.megabytes = s.bytes / double(1 << 20);
  r.modelError = errorAgainst(m, modelTruth);
  r.physicalError = errorAgainst(m, physical);
  r.cached = m.cached, r.warnings = s.warnings;
  r.image = writePicture(o, stem, toneMap.map(s.image));
  if (modelTruth)
    r.modelErrorMap =
        writePicture(o, stem + "-err-model",
                     rp::relativeErrorMap(s.image, modelTruth->result.image, o.errorScale));
  if (physical)
    r.physicalErrorMap =
        writePicture(o, stem + "-err-physical",
                     rp::relativeErrorMap(s.image, physical->result.image, o.errorScale));
  return r;
}

/// Error against time, every technique, both truths (circles: physical, crosses: model), and the
/// two Pareto fronts (marked by markFronts) as lines.
void writeParetoPlot(const std::string& path, const std::vector<rp::PageRow>& rows,
                     const std::string& title) {
  static const unsigned char palette[10][3] = {
      {31, 119, 180}, {255, 127, 14},  {44, 160, 44},   {214, 39, 40},  {148, 103, 189},
      {140, 86, 75},  {227, 119, 194}, {127, 127, 127}, {188, 189, 34}, {23, 190, 207}};
  std::vector<plot::Series> series;
  std::map<std::string, std::size_t> seriesOf;  // technique -> its physical series
  for (const auto& r : rows) {
    if (seriesOf.count(r.technique)) continue;
    const unsigned char* c = palette[seriesOf.size() % 10];
    seriesOf[r.technique] = series.size();
    series.push_back(
        {r.technique + " vs physical", {}, {}, {c[0], c[1], c[2]}, true, plot::Marker::Circle});
    series.push_back(
        {r.technique + " vs model", {}, {}, {c[0], c[1], c[2]}, true, plot::Marker::Cross});
  }
  plot::Series physicalFront{"front, physical truth", {}, {}, {0, 0, 0}, false};
  plot::Series modelFront{"front, model truths", {}, {}, {150, 150, 150}, false};
  std::vector<std::size_t> byTime(rows.size());  // the fronts as markFronts found them, in time
  for (std::size_t i = 0; i < rows.size(); ++i) byTime[i] = i;
  std::sort(byTime.begin(), byTime.end(),
            [&](std::size_t a, std::size_t b) { return rows[a].seconds < rows[b].seconds; });
  for (const auto& r : rows) {
    const std::size_t k = seriesOf[r.technique];
    series[k].x.push_back(r.seconds), series[k].y.push_back(r.physicalError);
    series[k + 1].x.push_back(r.seconds), series[k + 1].y.push_back(r.modelError);
  }
  for (std::size_t i : byTime) {
    const auto& r = rows[i];
    if (r.onPhysicalFront)
      physicalFront.x.push_back(r.seconds), physicalFront.y.push_back(r.physicalError);
    if (r.onModelFront) modelFront.x.push_back(r.seconds), modelFront.y.push_back(r.modelError);
  }
  for (auto* front : {&physicalFront, &modelFront})  // a line needs two points
    if (front->x.size() >= 2) series.push_back(*front);
  plot::ChartSpec spec;
  spec.title = title;
  spec.xLabel = "wall time, prepare + one frame (s)";
  spec.yLabel = "relative RMS error";
  spec.logX = spec.logY = true;
  spec.width = 1200, spec.height = 650;
  spec.legendOutside = true;  // every corner of the plot may hold a technique's points
  plot::writeLineChart(path, spec, series);
}

std::string commandLine(int argc, char** argv) {
  std::string s = "lucent";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    s += a.find_first_of(" \"'") == std::string::npos ? " " + a : " '" + a + "'";
  }
  return s;
}

void prepareFolders(const Options& o) {
  for (const std::string& folder : {o.out, o.out + "/img"}) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec || !std::filesystem::is_directory(folder))
      throw InputError("cannot create the report folder '" + folder +
                       "': " + (ec ? ec.message() : "a file of that name is in the way") +
                       "; choose another --out");
  }
  io::checkWritable(o.out + "/index.html");
}

rp::TruthEntry truthEntry(const Options& o, const std::string& role, const Measured& m,
                          const rp::ResultCache& cache, const image::ToneMap& toneMap) {
  const std::string stem = cache.stem(m.result.technique, m.result.knobs) + "-truth";
  return {role, m.result.technique, m.result.changedKnobs, m.result.seconds,
          writePicture(o, stem, toneMap.map(m.result.image))};
}
}  // namespace

int runReport(int argc, char** argv) {
  const lt::Registry& registry = lt::appRegistry();
  Args args("report", "lucent report [scene options] --out DIR [--truth both|physical|model]",
            reportOptionSpecs());
  if (!args.parseOptionsOnly(argc, argv)) return 0;
  const Options o = optionsOf(args);
  for (const lt::Technique& t : registry.all())  // every --truth-knob is checked before any work
    if (t.capabilities.groundTruth) truthKnobs(registry, t, args);
  prepareFolders(o);
  Scene scene = buildScene(args);
  const rp::ResultCache cache(o.out + "/cache", sceneKey(args));
  const lt::ShadeRequest request = lt::pixelRequest(scene.camera, scene);

  rp::ReportPage page;
  const std::vector<Job> jobs = settingsToRun(registry, scene, request, o, page.notRun);
  Runner runner(registry, scene, o, cache);
  const Truths truths = measureTruths(registry, args, o, jobs, runner, page.notRun);
  std::vector<Measured> measured;
  for (std::size_t i = 0; i < jobs.size(); ++i)
    if (auto m = runner.run(jobs[i],
                            "[" + std::to_string(i + 1) + "/" + std::to_string(jobs.size()) + "]",
                            page.notRun))
      measured.push_back(std::move(*m));

  const image::ToneMap toneMap = sharedToneMap(truths, measured);
  if (truths.physical)
    page.truths.push_back(truthEntry(o, "physical", *truths.physical, cache, toneMap));
  for (const auto& [model, m] : truths.byModel)
    page.truths.push_back(truthEntry(o, "model: " + model, m, cache, toneMap));
  for (const Measured& m : measured) page.rows.push_back(pageRow(o, cache, m, truths, toneMap));
  markFronts(page.rows);

  page.title = "Accuracy and cost: " + scene.meshName + ", " + scene.medium.material.name + ", " +
               std::to_string(int(std::lround(scene.sizeMm))) + " mm";
  page.scene = std::to_string(scene.camera.width) + " x " + std::to_string(scene.camera.height) +
               " pixels, " + std::to_string(request.points.size()) + " shaded; lights: ";
  for (const auto& l : scene.lightDescriptions) page.scene += l + "; ";
  page.command = commandLine(argc, argv);
  page.errorMapScale = o.errorScale;
  page.plot = "pareto.png";
  page.csv = "results.csv";
  writeParetoPlot(o.out + "/" + page.plot, page.rows, page.title);
  io::writeTextFile(o.out + "/" + page.csv, rp::pageCsv(page));
  io::writeTextFile(o.out + "/index.html", rp::pageHtml(page));
  std::printf("lucent report: %zu settings measured (%zu not run), %s/index.html\n",
              page.rows.size(), page.notRun.size(), o.out.c_str());
  return 0;
}

}  // namespace lucent::cli
