/// The `lucent` command line: dispatch, and bad input -> one line naming the problem and the fix,
/// exit 2.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include <lucent/technique/knob.hpp>
#include "../plot/line_chart.hpp"
#include "../util/error.hpp"
#include "commands.hpp"

namespace {

constexpr const char* kUsage =
    "usage: lucent COMMAND [options]   (lucent COMMAND --help for each)\n\n"
    "commands:\n"
    "  render      render a scene (built-in shape or mesh file) with a method, to EXR/PNG\n"
    "  profile     the dipole profile Rd(r) of a material as CSV, optionally plotted\n"
    "  materials   the measured materials and their derived dipole quantities\n"
    "  compare     error metrics of one image against a reference\n"
    "  bench       accuracy against time: sweep a method's knobs against a reference\n"
    "  techniques  every technique with its paper, capabilities and knobs (--json)\n"
    "  report      accuracy against time of every technique that fits a scene, as a web page\n"
    "  plan        the terms a scene calls for and the technique and knobs within a budget\n";

bool wantsPlot(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "report") == 0) return true;  // its page has a chart
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], "--plot", 6) == 0) return true;
  return false;
}

/// VTK on Debian draws charts through X. Without a display, run this same command under xvfb-run
/// (once: LUCENT_UNDER_XVFB stops a loop).
void reexecUnderXvfbIfNeeded(int argc, char** argv) {
  if (!wantsPlot(argc, argv) || lucent::plot::chartsAvailable() || std::getenv("LUCENT_UNDER_XVFB"))
    return;
  setenv("LUCENT_UNDER_XVFB", "1", 1);
  std::vector<char*> args{const_cast<char*>("xvfb-run"), const_cast<char*>("-a")};
  char self[4096];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) return;
  self[n] = '\0';
  args.push_back(self);
  for (int i = 1; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  execvp("xvfb-run", args.data());
  // exec failed: carry on; the chart writer reports the missing display with its fix.
}

}  // namespace

namespace lucent::cli {

int run(int argc, char** argv) {
  if (argc < 2) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  const std::string command = argv[1];
  if (command == "--help" || command == "-h" || command == "help") {
    std::fputs(kUsage, stdout);
    return 0;
  }
  reexecUnderXvfbIfNeeded(argc, argv);
  try {
    if (command == "render") return lucent::cli::runRender(argc, argv);
    if (command == "profile") return lucent::cli::runProfile(argc, argv);
    if (command == "materials") return lucent::cli::runMaterials(argc, argv);
    if (command == "compare") return lucent::cli::runCompare(argc, argv);
    if (command == "bench") return lucent::cli::runBench(argc, argv);
    if (command == "techniques") return lucent::cli::runTechniques(argc, argv);
    if (command == "report") return lucent::cli::runReport(argc, argv);
    if (command == "plan") return lucent::cli::runPlan(argc, argv);
    std::fprintf(stderr, "lucent: unknown command '%s'; run 'lucent --help' for the list\n",
                 command.c_str());
    return 2;
  } catch (const lucent::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const lucent::technique::RequestError& e) {
    std::fprintf(stderr, "lucent %s: %s\n", command.c_str(), e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lucent %s: internal error: %s\n", command.c_str(), e.what());
    return 1;
  }
}

}  // namespace lucent::cli
