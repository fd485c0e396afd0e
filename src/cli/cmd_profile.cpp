/// `lucent profile`: the dipole's radial profile Rd(r) as CSV (r_mm,R,G,B in mm^-2), and a chart.
#include <cstdio>
#include <iostream>

#include <lucent/optics/dipole.hpp>

#include "../plot/line_chart.hpp"
#include "commands.hpp"
#include "material_options.hpp"

namespace lucent::cli {

int runProfile(int argc, char** argv) {
  std::vector<OptionSpec> specs = materialOptionSpecs();
  specs.push_back({"r", "R1,R2,...", "distances in mm"});
  specs.push_back({"rmax", "X", "largest distance in mm, with --n evenly spaced points (default 10)"});
  specs.push_back({"n", "N", "number of points from 0 to --rmax (default 101)"});
  specs.push_back({"plot", "FILE.png", "draw Rd(r) per channel on a log scale (VTK charts)"});
  Args args("profile", "lucent profile --material NAME [--r R1,R2,... | --rmax X --n N] [--plot FILE.png]", specs);
  args.parse(argc, argv, 2);
  if (args.helpRequested()) {
    std::cout << args.helpText();
    return 0;
  }
  if (!args.positional().empty()) args.fail("unexpected argument '" + args.positional().front() + "'");
  if (args.has("r") && (args.has("rmax") || args.has("n"))) args.fail("give either --r or --rmax/--n, not both");
  const optics::Material m = materialFromArgs(args, "skin1");
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
