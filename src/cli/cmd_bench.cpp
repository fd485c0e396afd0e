/// `lucent bench`: the accuracy-cost harness. Renders one scene with a reference setting and with
/// every setting of a knob sweep, measures wall time and memory, computes each image's error
/// against the reference, and writes a CSV table and a PNG chart of error against time. It reads
/// each technique's default sweep, reference setting and typed statistics from the registry: it
/// names no technique.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include <lucent/image/metrics.hpp>

#include "../io/atomic_file.hpp"
#include "../plot/line_chart.hpp"
#include "../technique/techniques.hpp"
#include "../util/error.hpp"
#include "commands.hpp"
#include "process_stats.hpp"
#include "technique_run.hpp"

namespace lucent::cli {

namespace {
struct Row {
  std::string method, knobs, changedKnobs;
  double seconds = 0, memory = 0;
  technique::Statistics stats;
  image::ImageErrors errors;
};

using Sweeps = std::vector<technique::Sweep>;

/// "fraction=2,1,0.5" -> ("fraction", {"2","1","0.5"})
technique::Sweep parseSweep(const Args& args, const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    args.fail("--sweep '" + text + "' must be KNOB=V1,V2,..., e.g. fraction=2,1,0.5");
  std::vector<std::string> values;
  std::stringstream ss(text.substr(eq + 1));
  std::string v;
  while (std::getline(ss, v, ',')) values.push_back(v);
  return {text.substr(0, eq), values};
}

/// Time the baseline needs for `error`, by log-log interpolation between the baseline's settings
/// sorted by error (NaN outside their range: no extrapolation).
double baselineTimeAtError(std::vector<std::pair<double, double>> errorTime, double error) {
  std::sort(errorTime.begin(), errorTime.end());
  for (std::size_t i = 0; i + 1 < errorTime.size(); ++i) {
    const auto [e0, t0] = errorTime[i];
    const auto [e1, t1] = errorTime[i + 1];
    if (error < e0 || error > e1 || !(e0 > 0) || !(e1 > e0)) continue;
    const double f = std::log(error / e0) / std::log(e1 / e0);
    return std::exp(std::log(t0) + f * std::log(t1 / t0));
  }
  return std::nan("");
}

Sweeps sweepArgs(const Args& args, const std::string& option) {
  Sweeps out;
  for (const auto& s : args.all(option)) out.push_back(parseSweep(args, s));
  return out;
}

Row measure(const technique::Registry& registry, const technique::Technique& t, Scene& scene,
            const technique::KnobValues& knobs, bool progress, const image::Image& reference,
            const char* label) {
  std::fprintf(stderr, "lucent bench: %s %s (%s)\n", label, t.name.c_str(),
               knobs.summary(true).c_str());
  const ImageRun r = renderImage(registry, t, scene, knobs, progress);
  for (const auto& n : r.stats.warnings)
    std::fprintf(stderr, "lucent bench: warning: %s\n", n.c_str());
  return {t.name,
          knobs.summary(),
          knobs.summary(true),
          r.seconds,
          peakMemoryMiB(),
          r.stats,
          image::compareImages(r.image, reference)};
}
}  // namespace

int runBench(int argc, char** argv) {
  const technique::Registry& registry = technique::appRegistry();
  std::vector<OptionSpec> specs = sceneOptionSpecs();
  const std::string truth = registry.defaultReference().name;
  specs.push_back({"method", "NAME", "technique whose knobs are swept (default " + truth + ")"});
  specs.push_back({"knob", "NAME=VALUE", "a fixed knob of the swept technique", true});
  specs.push_back({"sweep", "KNOB=V1,V2,...",
                   "values of one knob; several --sweep give their product (default: the "
                   "technique's own sweep, `lucent techniques`)",
                   true});
  specs.push_back(
      {"reference-method", "NAME", "technique of the reference image (default " + truth + ")"});
  specs.push_back({"reference-knob", "NAME=VALUE",
                   "knob of the reference (default: the reference technique's converged setting)",
                   true});
  specs.push_back(
      {"baseline-method", "NAME",
       "also sweep a baseline technique and report each setting's speed-up at equal error"});
  specs.push_back({"baseline-sweep", "KNOB=V1,V2,...",
                   "the baseline's settings (default: its own sweep)", true});
  specs.push_back({"csv", "FILE", "write the table as CSV"});
  specs.push_back({"plot", "FILE.png", "chart of error (relative RMS) against time"});
  specs.push_back({"plot-x", "seconds|samples", "x axis of the chart (default seconds)"});
  specs.push_back({"quiet", "", "no progress bars"});
  Args args("bench",
            "lucent bench [scene options] [--method NAME --sweep KNOB=V1,V2,...] [--csv FILE] "
            "[--plot FILE.png]",
            specs);
  if (!args.parseOptionsOnly(argc, argv)) return 0;
  const std::string xAxis = args.get("plot-x", "seconds");
  if (xAxis != "seconds" && xAxis != "samples")
    args.fail("--plot-x must be seconds or samples, not '" + xAxis + "'");
  const technique::Technique& method = techniqueArg(registry, args, "method");
  const technique::Technique& refMethod = techniqueArg(registry, args, "reference-method");
  Sweeps sweeps = sweepArgs(args, "sweep");
  if (sweeps.empty()) sweeps = method.defaultSweep;
  if (sweeps.empty())
    args.fail("technique '" + method.name + "' has no default sweep: give --sweep KNOB=V1,V2,...");
  technique::KnobList refGiven = knobArgs(args, "reference-knob");
  if (refGiven.empty()) refGiven = refMethod.referenceKnobs;
  const technique::KnobValues refKnobs = refMethod.values(refGiven);

  // Every setting (swept and baseline) and every output is validated before anything runs.
  const std::vector<technique::KnobValues> settings =
      sweepSettings(method, knobArgs(args, "knob"), sweeps);
  const technique::Technique* baselineMethod =
      args.has("baseline-method") ? &registry.get(args.get("baseline-method")) : nullptr;
  Sweeps baselineSweeps = sweepArgs(args, "baseline-sweep");
  if (baselineMethod && baselineSweeps.empty()) baselineSweeps = baselineMethod->defaultSweep;
  const std::vector<technique::KnobValues> baselineSettings =
      baselineMethod ? sweepSettings(*baselineMethod, {}, baselineSweeps)
                     : std::vector<technique::KnobValues>{};
  std::vector<technique::KnobValues> all = settings;
  all.insert(all.end(), baselineSettings.begin(), baselineSettings.end());
  all.push_back(refKnobs);
  std::vector<NamedOutput> written = knobOutputs(all);
  for (const char* option : {"csv", "plot"})
    if (args.has(option)) written.push_back({std::string("--") + option, args.get(option)});
  checkOutputs(args, written, sceneInputFiles(args));

  Scene scene = buildScene(args);
  const bool progress = !args.has("quiet");
  std::fprintf(stderr, "lucent bench: reference %s (%s)\n", refMethod.name.c_str(),
               refKnobs.summary().c_str());
  const ImageRun ref = renderImage(registry, refMethod, scene, refKnobs, progress);
  for (const auto& n : ref.stats.warnings)
    std::fprintf(stderr, "lucent bench: reference warning: %s\n", n.c_str());

  std::vector<Row> rows;
  for (std::size_t i = 0; i < settings.size(); ++i) {
    const std::string label =
        "[" + std::to_string(i + 1) + "/" + std::to_string(settings.size()) + "]";
    rows.push_back(
        measure(registry, method, scene, settings[i], progress, ref.image, label.c_str()));
  }

  // Baseline curve (error -> time), measured in the same run, for speed-ups at equal error.
  std::vector<Row> baseline;
  std::vector<std::pair<double, double>> baselineCurve;
  for (const technique::KnobValues& k : baselineSettings) {
    baseline.push_back(
        measure(registry, *baselineMethod, scene, k, progress, ref.image, "baseline"));
    baselineCurve.push_back({baseline.back().errors.relativeRms, baseline.back().seconds});
  }

  // Columns from the typed statistics only: the same for every technique.
  std::ostringstream csv;
  csv << "method,knobs,seconds,prepare_seconds,frame_seconds,samples,sample_unit,bytes,peak_memory_"
         "mib,"
         "rmse_tonemapped,relative_rms,max_abs_error,speedup_vs_reference,speedup_at_equal_error\n";
  std::printf("reference: %s (%s), %.2f s, %.0f %s\n", refMethod.name.c_str(),
              refKnobs.summary(true).c_str(), ref.seconds, ref.stats.samples,
              ref.stats.sampleUnit.c_str());
  // speedup: reference time / this time; at equal error: the baseline's interpolated time / this
  // time.
  std::printf("%-40s %9s %9s %9s %11s %9s %12s %12s %8s %9s\n", "knobs", "seconds", "prepare_s",
              "frame_s", "samples", "data_MiB", "rmse_tone", "rel_rms", "speedup", "eq_error");
  auto emit = [&](const Row& r, bool isBaseline) {
    const double eq = isBaseline
                          ? std::nan("")
                          : baselineTimeAtError(baselineCurve, r.errors.relativeRms) / r.seconds;
    const technique::Statistics& st = r.stats;
    csv << r.method << ",\"" << r.knobs << "\"," << r.seconds << "," << st.totalPrepareSeconds()
        << "," << st.totalFrameSeconds() << "," << st.samples << ",\"" << st.sampleUnit << "\","
        << st.bytes << "," << r.memory << "," << r.errors.rmseToneMapped << ","
        << r.errors.relativeRms << "," << r.errors.maxAbsError << "," << ref.seconds / r.seconds
        << "," << eq << "\n";
    std::printf("%-40s %9.3f %9.3f %9.3f %11.0f %9.2f %12.3e %12.3e %8.1f %9.2f\n",
                ((isBaseline ? "[" + r.method + "] " : std::string()) + r.changedKnobs).c_str(),
                r.seconds, st.totalPrepareSeconds(), st.totalFrameSeconds(), st.samples,
                st.bytes / double(1 << 20), r.errors.rmseToneMapped, r.errors.relativeRms,
                ref.seconds / r.seconds, eq);
  };
  for (const Row& r : rows) emit(r, false);
  for (const Row& r : baseline) emit(r, true);
  if (args.has("csv")) io::writeTextFile(args.get("csv"), csv.str());
  if (args.has("plot")) {
    auto xOf = [&](const Row& r) {
      if (xAxis == "seconds") return r.seconds;
      return r.stats.samples;
    };
    plot::Series s{method.name, {}, {}, {214, 39, 40}, true};
    for (const Row& r : rows) {
      s.x.push_back(xOf(r));
      s.y.push_back(r.errors.relativeRms);
    }
    plot::Series line = s;
    line.points = false;
    line.name = method.name + " (sweep order)";
    plot::ChartSpec spec;
    spec.title = "Error against time: " + scene.meshName + ", " + scene.medium.material.name +
                 ", " + std::to_string(int(std::lround(scene.sizeMm))) + " mm";
    spec.xLabel = xAxis == "seconds" ? "wall time (s)"
                                     : (rows.empty() ? "samples" : rows.front().stats.sampleUnit);
    spec.yLabel = "relative RMS error vs reference";
    spec.logX = spec.logY = true;
    std::vector<plot::Series> series{line, s};
    if (!baseline.empty()) {
      plot::Series b{baseline.front().method + " (baseline)", {}, {}, {31, 119, 180}, true};
      for (const Row& r : baseline) b.x.push_back(xOf(r)), b.y.push_back(r.errors.relativeRms);
      series.push_back(b);
    }
    plot::writeLineChart(args.get("plot"), spec, series);
  }
  return 0;
}

}  // namespace lucent::cli
