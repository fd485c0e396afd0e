/// `lucent profile`: the dipole's radial profile Rd(r) as CSV (r_mm,R,G,B in mm^-2), and a chart.
#include <cstdio>
#include <iostream>

#include <lucent/optics/dipole.hpp>
#include <lucent/reference/pencil_beam_mc.hpp>

#include "../plot/line_chart.hpp"
#include "../util/progress_bar.hpp"
#include "../util/tbb_parallel.hpp"
#include "commands.hpp"
#include "material_options.hpp"

namespace lucent::cli {

namespace {
/// The Monte Carlo profile: ring-averaged Rd at ring centres with standard errors, the totals against the
/// dipole's on stderr, and a chart of both.
int runPathTracedProfile(const Args& args, const optics::Material& m) {
  if (args.has("r")) args.fail("--method pathtrace tallies rings: give --rmax and --n (the ring count), not --r");
  reference::PencilBeamSettings s;
  s.rMax = args.number("rmax", 10.0, 1e-9, 1e9);
  s.rings = args.integer("n", 100, 1, 100000);
  s.photons = std::uint64_t(args.number("photons", 1e6, 1, 1e11));
  s.g = args.number("g", 0.0, -0.99, 0.99);
  s.seed = std::uint64_t(args.number("seed", 1, 0, 1e15));
  s.eta = m.eta;
  const auto dipole = optics::Dipole<double>::make(m.sigmaA, m.sigmaSPrime, m.eta);
  reference::RadialProfile channel[3];
  for (int c = 0; c < 3; ++c) {
    s.sigmaA = m.sigmaA[c];
    s.sigmaS = m.sigmaSPrime[c] / (1 - s.g);
    if (!(s.sigmaA + s.sigmaS > 0)) args.fail("channel " + std::to_string(c) + " has no extinction: nothing to simulate");
    util::ProgressBar bar(std::string("photons, channel ") + "RGB"[c], !args.has("quiet"));
    channel[c] = reference::simulatePencilBeam(s, util::tbbFor, [&](double f) { bar.update(f); });
    bar.finish();
    if (channel[c].droppedPhotons)
      std::fprintf(stderr, "lucent profile: warning: %llu photons of channel %c exceeded %llu collisions and were dropped\n",
                   static_cast<unsigned long long>(channel[c].droppedPhotons), "RGB"[c],
                   static_cast<unsigned long long>(s.maxCollisions));
  }
  std::printf("r_mm,R,G,B,R_se,G_se,B_se\n");
  plot::Series mc[3] = {{"R Monte Carlo", {}, {}, {214, 39, 40}, true}, {"G Monte Carlo", {}, {}, {44, 160, 44}, true},
                        {"B Monte Carlo", {}, {}, {31, 119, 180}, true}};
  plot::Series dp[3] = {{"R dipole", {}, {}, {214, 39, 40}}, {"G dipole", {}, {}, {44, 160, 44}}, {"B dipole", {}, {}, {31, 119, 180}}};
  for (int i = 0; i < s.rings; ++i) {
    const double r = 0.5 * (channel[0].rInner[std::size_t(i)] + channel[0].rOuter[std::size_t(i)]);
    std::printf("%.10g", r);
    for (const auto& ch : channel) std::printf(",%.10g", ch.rd[std::size_t(i)]);
    for (const auto& ch : channel) std::printf(",%.10g", ch.rdStdError[std::size_t(i)]);
    std::printf("\n");
    for (int c = 0; c < 3; ++c) {
      mc[c].x.push_back(r);
      mc[c].y.push_back(channel[c].rd[std::size_t(i)]);
      dp[c].x.push_back(r);
      dp[c].y.push_back(dipole.channel[c].rd(r));
    }
  }
  for (int c = 0; c < 3; ++c)
    std::fprintf(stderr, "total diffuse reflectance %c: Monte Carlo %.5f +- %.5f, dipole %.5f\n", "RGB"[c],
                 channel[c].total, channel[c].totalStdError, dipole.channel[c].total());
  if (args.has("plot")) {
    plot::ChartSpec spec;
    spec.title = "Rd(r), " + m.name + ": Monte Carlo pencil beam (points) against the dipole (lines)";
    spec.xLabel = "r (mm)";
    spec.yLabel = "Rd (1/mm^2)";
    spec.logY = true;
    plot::writeLineChart(args.get("plot"), spec, {dp[0], dp[1], dp[2], mc[0], mc[1], mc[2]});
  }
  return 0;
}
}  // namespace

int runProfile(int argc, char** argv) {
  std::vector<OptionSpec> specs = materialOptionSpecs();
  specs.push_back({"r", "R1,R2,...", "distances in mm"});
  specs.push_back({"rmax", "X", "largest distance in mm, with --n evenly spaced points (default 10)"});
  specs.push_back({"n", "N", "number of points from 0 to --rmax (default 101)"});
  specs.push_back({"plot", "FILE.png", "draw Rd(r) per channel on a log scale (VTK charts)"});
  specs.push_back({"method", "dipole|pathtrace", "dipole formula (default) or Monte Carlo pencil beam on a semi-infinite medium"});
  specs.push_back({"photons", "N", "pathtrace: photons per channel (default 1000000)"});
  specs.push_back({"g", "G", "pathtrace: HG mean cosine; sigma_s = sigma_s'/(1-g) (default 0)"});
  specs.push_back({"seed", "S", "pathtrace: random seed (default 1)"});
  specs.push_back({"quiet", "", "no progress bar"});
  Args args("profile", "lucent profile --material NAME [--method dipole|pathtrace] [--r R1,R2,... | --rmax X --n N] [--plot FILE.png]", specs);
  args.parse(argc, argv, 2);
  if (args.helpRequested()) {
    std::cout << args.helpText();
    return 0;
  }
  if (!args.positional().empty()) args.fail("unexpected argument '" + args.positional().front() + "'");
  if (args.has("r") && (args.has("rmax") || args.has("n"))) args.fail("give either --r or --rmax/--n, not both");
  const optics::Material m = materialFromArgs(args, "skin1");
  const std::string method = args.get("method", "dipole");
  if (method != "dipole" && method != "pathtrace") args.fail("--method must be dipole or pathtrace, not '" + method + "'");
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
  const auto dipole = optics::Dipole<double>::make(m.sigmaA, m.sigmaSPrime, m.eta);
  std::printf("r_mm,R,G,B\n");
  plot::Series series[3] = {{"R", {}, {}, {214, 39, 40}}, {"G", {}, {}, {44, 160, 44}}, {"B", {}, {}, {31, 119, 180}}};
  for (double r : radii) {
    const auto rd = dipole.rd(r);
    std::printf("%.10g,%.10g,%.10g,%.10g\n", r, rd.x, rd.y, rd.z);
    for (int c = 0; c < 3; ++c) {
      series[c].x.push_back(r);
      series[c].y.push_back(rd[c]);
    }
  }
  if (args.has("plot")) {
    plot::ChartSpec spec;
    spec.title = "Dipole Rd(r), " + m.name + " (eta " + std::to_string(m.eta).substr(0, 4) + ")";
    spec.xLabel = "r (mm)";
    spec.yLabel = "Rd (1/mm^2)";
    spec.logY = true;
    plot::writeLineChart(args.get("plot"), spec, {series[0], series[1], series[2]});
  }
  return 0;
}

}  // namespace lucent::cli
