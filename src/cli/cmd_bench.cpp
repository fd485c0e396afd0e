/// `lucent bench`: the accuracy-cost harness. Renders one scene with a reference setting and with every
/// setting of a knob sweep, measures wall time and memory, computes each image's error against the
/// reference, and writes a CSV table and a PNG chart of error against time.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include <lucent/image/metrics.hpp>

#include "../io/atomic_file.hpp"
#include "../plot/line_chart.hpp"
#include "../render/methods.hpp"
#include "../util/error.hpp"
#include "commands.hpp"
#include "process_stats.hpp"

namespace lucent::cli {

namespace {
struct Row {
  std::string method, knobs, changedKnobs;
  double seconds = 0, memory = 0;
  std::map<std::string, double> figures;
  image::ImageErrors errors;
};

/// "fraction=2,1,0.5" -> ("fraction", {"2","1","0.5"})
std::pair<std::string, std::vector<std::string>> parseSweep(const Args& args, const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    args.fail("--sweep '" + text + "' must be KNOB=V1,V2,..., e.g. fraction=2,1,0.5");
  std::vector<std::string> values;
  std::stringstream ss(text.substr(eq + 1));
  std::string v;
  while (std::getline(ss, v, ',')) values.push_back(v);
  return {text.substr(0, eq), values};
}

/// Time the baseline needs for `error`, by log-log interpolation between the baseline's settings sorted
/// by error (NaN outside their range: no extrapolation).
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

/// The product of the sweeps, each setting combined with the fixed knobs and validated.
std::vector<render::Knobs> sweepSettings(const render::Method& method, const std::map<std::string, std::string>& fixed,
                                         const std::vector<std::pair<std::string, std::vector<std::string>>>& sweeps) {
  std::vector<std::map<std::string, std::string>> combos{fixed};
  for (const auto& [name, values] : sweeps) {
    std::vector<std::map<std::string, std::string>> next;
    for (const auto& c : combos)
      for (const auto& v : values) {
        auto k = c;
        k[name] = v;
        next.push_back(k);
      }
    combos.swap(next);
  }
  std::vector<render::Knobs> settings;
  for (const auto& c : combos) settings.emplace_back(method.knobs, c, method.name);
  return settings;
}

std::map<std::string, std::string> knobArgs(const Args& args, const std::string& option) {
  std::map<std::string, std::string> out;
  for (const auto& k : args.all(option))
    for (const auto& [name, value] : render::parseKnobList(k)) out[name] = value;
  return out;
}
}  // namespace

int runBench(int argc, char** argv) {
  std::vector<OptionSpec> specs = sceneOptionSpecs();
  specs.push_back({"method", "NAME", "method whose knobs are swept (default reference)"});
  specs.push_back({"knob", "NAME=VALUE", "a fixed knob of the swept method", true});
  specs.push_back({"sweep", "KNOB=V1,V2,...", "values of one knob; several --sweep give their product (default for reference: fraction=2,1,0.5,0.25)", true});
  specs.push_back({"reference-method", "NAME", "method of the reference image (default reference)"});
  specs.push_back({"reference-knob", "NAME=VALUE", "knob of the reference (default for reference: fraction=0.125)", true});
  specs.push_back({"baseline-method", "NAME", "also sweep a baseline method and report each setting's speed-up at equal error"});
  specs.push_back({"baseline-sweep", "KNOB=V1,V2,...", "the baseline's settings (e.g. epsilon=3,1,0.3,0.1 for jensen-buhler)", true});
  specs.push_back({"csv", "FILE", "write the table as CSV"});
  specs.push_back({"plot", "FILE.png", "chart of error (relative RMS) against time"});
  specs.push_back({"plot-x", "seconds|samples", "x axis of the chart (default seconds)"});
  specs.push_back({"quiet", "", "no progress bars"});
  Args args("bench", "lucent bench [scene options] [--method NAME --sweep KNOB=V1,V2,...] [--csv FILE] [--plot FILE.png]", specs);
  args.parse(argc, argv, 2);
  if (args.helpRequested()) {
    std::cout << args.helpText();
    return 0;
  }
  if (!args.positional().empty()) args.fail("unexpected argument '" + args.positional().front() + "'");
  const std::string xAxis = args.get("plot-x", "seconds");
  if (xAxis != "seconds" && xAxis != "samples") args.fail("--plot-x must be seconds or samples, not '" + xAxis + "'");
  const render::Method& method = render::findMethod(args.get("method", "reference"));
  const render::Method& refMethod = render::findMethod(args.get("reference-method", "reference"));
  std::vector<std::pair<std::string, std::vector<std::string>>> sweeps;
  for (const auto& s : args.all("sweep")) sweeps.push_back(parseSweep(args, s));
  if (sweeps.empty()) {
    if (method.name != "reference") args.fail("give the knob values to sweep with --sweep KNOB=V1,V2,...");
    sweeps.push_back({"fraction", {"2", "1", "0.5", "0.25"}});
  }
  auto refGiven = knobArgs(args, "reference-knob");
  if (refGiven.empty() && refMethod.name == "reference") refGiven["fraction"] = "0.125";
  const render::Knobs refKnobs(refMethod.knobs, refGiven, refMethod.name);

  // Every setting (swept and baseline) is validated before anything runs.
  const std::vector<render::Knobs> settings = sweepSettings(method, knobArgs(args, "knob"), sweeps);
  const render::Method* baselineMethod = args.has("baseline-method") ? &render::findMethod(args.get("baseline-method")) : nullptr;
  std::vector<std::pair<std::string, std::vector<std::string>>> baselineSweeps;
  for (const auto& text : args.all("baseline-sweep")) baselineSweeps.push_back(parseSweep(args, text));
  const std::vector<render::Knobs> baselineSettings =
      baselineMethod ? sweepSettings(*baselineMethod, {}, baselineSweeps) : std::vector<render::Knobs>{};

  const Scene scene = buildScene(args);
  const bool progress = !args.has("quiet");
  std::fprintf(stderr, "lucent bench: reference %s (%s)\n", refMethod.name.c_str(), refKnobs.summary().c_str());
  const render::RenderResult ref = refMethod.run(scene, refKnobs, progress);
  for (const auto& n : ref.notes) std::fprintf(stderr, "lucent bench: reference warning: %s\n", n.c_str());

  std::vector<Row> rows;
  for (std::size_t i = 0; i < settings.size(); ++i) {
    std::fprintf(stderr, "lucent bench: [%zu/%zu] %s (%s)\n", i + 1, settings.size(), method.name.c_str(),
                 settings[i].summary().c_str());
    const render::RenderResult r = method.run(scene, settings[i], progress);
    for (const auto& n : r.notes) std::fprintf(stderr, "lucent bench: warning: %s\n", n.c_str());
    rows.push_back({method.name, settings[i].summary(), settings[i].summary(true), r.seconds, peakMemoryMiB(), r.figures,
                    image::compareImages(r.image, ref.image)});
  }

  // Baseline curve (error -> time), measured in the same run, for speed-ups at equal error.
  std::vector<Row> baseline;
  std::vector<std::pair<double, double>> baselineCurve;
  for (const render::Knobs& k : baselineSettings) {
    std::fprintf(stderr, "lucent bench: baseline %s (%s)\n", baselineMethod->name.c_str(), k.summary(true).c_str());
    const render::RenderResult r = baselineMethod->run(scene, k, progress);
    baseline.push_back({baselineMethod->name, k.summary(), k.summary(true), r.seconds, peakMemoryMiB(), r.figures,
                        image::compareImages(r.image, ref.image)});
    baselineCurve.push_back({baseline.back().errors.relativeRms, r.seconds});
  }

  std::ostringstream csv;
  csv << "method,knobs,seconds,frame_seconds,evaluation_seconds,samples,peak_memory_mib,spacing_mm,surface_samples,rmse_tonemapped,"
         "relative_rms,max_abs_error,speedup_vs_reference,speedup_at_equal_error\n";
  auto fig = [](const std::map<std::string, double>& f, const char* k) {
    const auto it = f.find(k);
    return it == f.end() ? std::nan("") : it->second;
  };
  std::printf("reference: %s (%s), %.2f s, %.0f samples\n", refMethod.name.c_str(), refKnobs.summary(true).c_str(),
              ref.seconds, fig(ref.figures, "surface_samples"));
  // speedup: reference time / this time; at equal error: the baseline's interpolated time / this time.
  std::printf("%-40s %9s %9s %9s %9s %11s %12s %12s %8s %9s\n", "knobs", "seconds", "frame_s", "eval_s", "spacing",
              "samples", "rmse_tone", "rel_rms", "speedup", "eq_error");
  auto emit = [&](const Row& r, bool isBaseline) {
    const double eq = isBaseline ? std::nan("") : baselineTimeAtError(baselineCurve, r.errors.relativeRms) / r.seconds;
    const double samples = r.figures.count("samples") ? fig(r.figures, "samples") : fig(r.figures, "surface_samples");
    csv << r.method << ",\"" << r.knobs << "\"," << r.seconds << "," << fig(r.figures, "frame_seconds") << "," << fig(r.figures, "evaluation_seconds") << "," << samples
        << "," << r.memory << "," << fig(r.figures, "spacing_mm") << "," << fig(r.figures, "surface_samples") << ","
        << r.errors.rmseToneMapped << "," << r.errors.relativeRms << "," << r.errors.maxAbsError << ","
        << ref.seconds / r.seconds << "," << eq << "\n";
    std::printf("%-40s %9.3f %9.3f %9.3f %9.4g %11.0f %12.3e %12.3e %8.1f %9.2f\n",
                ((isBaseline ? "[" + r.method + "] " : std::string()) + r.changedKnobs).c_str(), r.seconds,
                fig(r.figures, "frame_seconds"), fig(r.figures, "evaluation_seconds"), fig(r.figures, "spacing_mm"), samples, r.errors.rmseToneMapped,
                r.errors.relativeRms, ref.seconds / r.seconds, eq);
  };
  for (const Row& r : rows) emit(r, false);
  for (const Row& r : baseline) emit(r, true);
  if (args.has("csv")) io::writeTextFile(args.get("csv"), csv.str());
  if (args.has("plot")) {
    auto xOf = [&](const Row& r) {
      if (xAxis == "seconds") return r.seconds;
      return r.figures.count("samples") ? fig(r.figures, "samples") : fig(r.figures, "surface_samples");
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
    spec.title = "Error against time: " + scene.meshName + ", " + scene.material.name + ", " +
                 std::to_string(int(std::lround(scene.sizeMm))) + " mm";
    spec.xLabel = xAxis == "seconds" ? "wall time (s)" : "samples";
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
