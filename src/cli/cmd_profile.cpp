/// `lucent profile`: a diffusion profile's R(r) as CSV (r_mm,R,G,B in mm^-2), and a chart; or the
/// Monte Carlo pencil beam against the profiles.
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include <lucent/optics/profile.hpp>
#include <lucent/reference/pencil_beam_mc.hpp>

#include "../plot/line_chart.hpp"
#include "../util/progress_bar.hpp"
#include "../util/tbb_parallel.hpp"
#include "commands.hpp"
#include "material_options.hpp"
#include "output_paths.hpp"

namespace lucent::cli {

namespace {
/// The Monte Carlo profile: ring-averaged Rd at ring centres with standard errors, the totals
/// against the dipole's on stderr, and a chart of both. The profiles --model names (a
/// comma-separated list, or "all").
std::vector<optics::ProfileModel> modelsFromArgs(const Args& args, const std::string& fallback) {
  std::vector<optics::ProfileModel> models;
  const std::string given = args.get("model", fallback);
  if (given == "all") {
    for (const auto& info : optics::kProfileModels) models.push_back(info.model);
    return models;
  }
  std::size_t start = 0;
  while (start <= given.size()) {
    const std::size_t end = std::min(given.find(',', start), given.size());
    try {
      models.push_back(optics::profileModelNamed(given.substr(start, end - start)));
    } catch (const std::invalid_argument& e) {
      args.fail(std::string("--model: ") + e.what() + ", or all");
    }
    start = end + 1;
  }
  return models;
}

std::vector<optics::Profile<double>> profilesOf(const std::vector<optics::ProfileModel>& models,
                                                const optics::Material& m) {
  std::vector<optics::Profile<double>> out;
  for (auto model : models)
    out.push_back(optics::Profile<double>::make(model, m.sigmaA, m.sigmaSPrime, m.eta));
  return out;
}

std::string modelName(const optics::Profile<double>& p) {
  return std::string(optics::profileModelInfo(p.model).name);
}

/// A chart series coloured by channel (one profile) or by profile (several; the palette of the
/// profiles' order in kProfileModels).
plot::Series seriesOf(const std::string& name, int channel, int profileIndex, bool points = false) {
  static const unsigned char channelColour[3][3] = {{214, 39, 40}, {44, 160, 44}, {31, 119, 180}};
  static const unsigned char profileColour[6][3] = {
      {0, 0, 0}, {148, 103, 189}, {255, 127, 14}, {23, 190, 207}, {140, 86, 75}, {227, 119, 194}};
  plot::Series s;
  s.name = name;
  const unsigned char* rgb =
      profileIndex < 0 ? channelColour[channel] : profileColour[profileIndex % 6];
  for (int k = 0; k < 3; ++k) s.rgb[k] = rgb[k];
  s.points = points;
  return s;
}

int runPathTracedProfile(const Args& args, const optics::Material& m) {
  if (args.has("r"))
    args.fail("--method pathtrace tallies rings: give --rmax and --n (the ring count), not --r");
  reference::PencilBeamSettings s;
  s.rMax = args.number("rmax", 10.0, 1e-9, 1e9);
  s.rings = args.integer("n", 100, 1, 100000);
  s.photons = std::uint64_t(args.number("photons", 1e6, 1, 1e11));
  s.g = args.number("g", 0.0, -0.99, 0.99);
  s.seed = std::uint64_t(args.number("seed", 1, 0, 1e15));
  const std::string orders = args.get("orders", "all");
  if (orders == "single")
    s.maxOrder = 1;
  else if (orders == "multiple")
    s.minOrder = 2;
  else if (orders != "all")
    args.fail("--orders must be all, single or multiple, not '" + orders + "'");
  s.eta = m.eta;
  const auto profiles = profilesOf(modelsFromArgs(args, "dipole"), m);
  reference::RadialProfile channel[3];
  for (int c = 0; c < 3; ++c) {
    s.sigmaA = m.sigmaA[c];
    s.sigmaS = m.sigmaSPrime[c] / (1 - s.g);
    if (!(s.sigmaA + s.sigmaS > 0))
      args.fail("channel " + std::to_string(c) + " has no extinction: nothing to simulate");
    util::ProgressBar bar(std::string("photons, channel ") + "RGB"[c], !args.has("quiet"));
    channel[c] = reference::simulatePencilBeam(s, util::tbbFor, [&](double f) { bar.update(f); });
    bar.finish();
    if (channel[c].droppedPhotons)
      std::fprintf(stderr,
                   "lucent profile: warning: %llu photons of channel %c exceeded %llu collisions "
                   "and were dropped\n",
                   static_cast<unsigned long long>(channel[c].droppedPhotons), "RGB"[c],
                   static_cast<unsigned long long>(s.maxCollisions));
  }
  std::printf("r_mm,R,G,B,R_se,G_se,B_se\n");
  std::vector<plot::Series> series;
  for (int c = 0; c < 3; ++c)
    series.push_back(seriesOf(std::string(1, "RGB"[c]) + " Monte Carlo", c, -1, true));
  for (std::size_t k = 0; k < profiles.size(); ++k)
    for (int c = 0; c < 3; ++c)
      series.push_back(seriesOf(std::string(1, "RGB"[c]) + " " + modelName(profiles[k]), c,
                                profiles.size() > 1 ? int(k) + 1 : -1));
  for (int i = 0; i < s.rings; ++i) {
    const double r = 0.5 * (channel[0].rInner[std::size_t(i)] + channel[0].rOuter[std::size_t(i)]);
    std::printf("%.10g", r);
    for (const auto& ch : channel) std::printf(",%.10g", ch.rd[std::size_t(i)]);
    for (const auto& ch : channel) std::printf(",%.10g", ch.rdStdError[std::size_t(i)]);
    std::printf("\n");
    for (std::size_t k = 0; k < series.size(); ++k) {
      const int c = int(k % 3);
      series[k].x.push_back(r);
      series[k].y.push_back(k < 3 ? channel[c].rd[std::size_t(i)]
                                  : profiles[k / 3 - 1].channel[c].rd(r));
    }
  }
  for (int c = 0; c < 3; ++c) {
    std::fprintf(stderr, "total diffuse reflectance %c: Monte Carlo %.5f +- %.5f", "RGB"[c],
                 channel[c].total, channel[c].totalStdError);
    for (const auto& p : profiles)
      std::fprintf(stderr, ", %s %.5f", modelName(p).c_str(), p.channel[c].total());
    std::fprintf(stderr, "\n");
  }
  if (args.has("plot")) {
    plot::ChartSpec spec;
    spec.title =
        "Rd(r), " + m.name + ": Monte Carlo pencil beam (points) against the profiles (lines)";
    spec.xLabel = "r (mm)";
    spec.yLabel = "Rd (1/mm^2)";
    spec.logY = true;
    plot::writeLineChart(args.get("plot"), spec, series);
  }
  return 0;
}
}  // namespace

int runProfile(int argc, char** argv) {
  std::vector<OptionSpec> specs = materialOptionSpecs();
  specs.push_back({"r", "R1,R2,...", "distances in mm"});
  specs.push_back(
      {"rmax", "X", "largest distance in mm, with --n evenly spaced points (default 10)"});
  specs.push_back({"n", "N", "number of points from 0 to --rmax (default 101)"});
  specs.push_back({"plot", "FILE.png", "draw Rd(r) per channel on a log scale (VTK charts)"});
  std::string modelNames;
  for (const auto& info : optics::kProfileModels)
    modelNames += (modelNames.empty() ? "" : "|") + std::string(info.name);
  specs.push_back(
      {"method", "profile|pathtrace",
       "a profile's formula (default) or Monte Carlo pencil beam on a semi-infinite medium"});
  specs.push_back(
      {"model", modelNames + "|all",
       "the profile(s), comma-separated (default dipole); with pathtrace, drawn against it"});
  specs.push_back({"photons", "N", "pathtrace: photons per channel (default 1000000)"});
  specs.push_back({"g", "G", "pathtrace: HG mean cosine; sigma_s = sigma_s'/(1-g) (default 0)"});
  specs.push_back({"seed", "S", "pathtrace: random seed (default 1)"});
  specs.push_back(
      {"orders", "all|single|multiple", "pathtrace: which scattering orders leave (default all)"});
  specs.push_back({"quiet", "", "no progress bar"});
  Args args(
      "profile",
      "lucent profile --material NAME [--model " + modelNames +
          "|all] [--method profile|pathtrace] [--r R1,R2,... | --rmax X --n N] [--plot FILE.png]",
      specs);
  if (!args.parseOptionsOnly(argc, argv)) return 0;
  if (args.has("plot")) checkOutputs(args, {{"--plot", args.get("plot")}});
  if (args.has("r") && (args.has("rmax") || args.has("n")))
    args.fail("give either --r or --rmax/--n, not both");
  const optics::Material m = materialFromArgs(args, "skin1");
  std::string method = args.get("method", "profile");
  if (method == "dipole") method = "profile";  // the name before there were several profiles
  if (method != "profile" && method != "pathtrace")
    args.fail("--method must be profile or pathtrace, not '" + method + "'");
  if (method == "pathtrace") return runPathTracedProfile(args, m);
  std::vector<double> radii;
  if (args.has("r")) {
    radii = args.list("r");
    for (double r : radii)
      if (r < 0) args.fail("--r: distances must be >= 0, got " + std::to_string(r));
  } else {
    const double rmax = args.number("rmax", 10.0, 1e-9, 1e9);
    const int n = args.integer("n", 101, 2, 10000000);
    for (int i = 0; i < n; ++i) radii.push_back(rmax * i / (n - 1));
  }
  const auto profiles = profilesOf(modelsFromArgs(args, "dipole"), m);
  std::printf("r_mm");
  for (const auto& p : profiles)
    for (char c : {'R', 'G', 'B'})
      std::printf(profiles.size() > 1 ? ",%c_%s" : ",%c", c, modelName(p).c_str());
  std::printf("\n");
  std::vector<plot::Series> series;
  for (std::size_t k = 0; k < profiles.size(); ++k)
    for (int c = 0; c < 3; ++c)
      series.push_back(seriesOf(
          std::string(1, "RGB"[c]) + (profiles.size() > 1 ? " " + modelName(profiles[k]) : ""), c,
          profiles.size() > 1 ? int(k) : -1));
  for (double r : radii) {
    std::printf("%.10g", r);
    for (std::size_t k = 0; k < series.size(); ++k) {
      const double v = profiles[k / 3].channel[k % 3].rd(r);
      std::printf(",%.10g", v);
      series[k].x.push_back(r);
      series[k].y.push_back(v);
    }
    std::printf("\n");
  }
  if (args.has("plot")) {
    plot::ChartSpec spec;
    spec.title = "R(r), " + m.name + " (eta " + std::to_string(m.eta).substr(0, 4) + ")";
    spec.xLabel = "r (mm)";
    spec.yLabel = "R (1/mm^2)";
    spec.logY = true;
    plot::writeLineChart(args.get("plot"), spec, series);
  }
  return 0;
}

}  // namespace lucent::cli
