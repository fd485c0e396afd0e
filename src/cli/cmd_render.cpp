/// `lucent render`: renders a scene with one technique of the registry and writes EXR/PNG images
/// and a JSON stats file.
#include <cstdio>
#include <iostream>
#include <optional>
#include <tuple>

#include <lucent/plan/explain.hpp>
#include "../io/atomic_file.hpp"

#include "../technique/techniques.hpp"
#include "../util/error.hpp"
#include "commands.hpp"
#include "image_output.hpp"
#include "json_writer.hpp"
#include "plan_setup.hpp"
#include "process_stats.hpp"
#include "technique_run.hpp"

namespace lucent::cli {

namespace {
std::string techniqueHelp(const technique::Registry& registry) {
  std::string s =
      "\nmethods and their knobs (--knob NAME=VALUE; `lucent techniques` for ranges and "
      "capabilities):\n";
  for (const auto& t : registry.all()) {
    s += "  " + t.name + ": " + t.summary + "\n";
    for (const auto& k : t.knobs)
      s += "      " + k.name + " (default " + (k.defaultValue.empty() ? "none" : k.defaultValue) +
           "): " + k.help + "\n";
  }
  return s;
}

std::string statsJson(const Scene& scene, const technique::Technique& t,
                      const technique::KnobValues& knobs, const ImageRun& run) {
  JsonObject knobJson, figures, material;
  for (const auto& [k, v] : knobs.values()) knobJson.add(k, v);
  for (const auto& [k, v] : run.figures) figures.add(k, v);
  const optics::Material& m = scene.medium.material;
  material.add("name", m.name).add("eta", m.eta);
  for (int c = 0; c < 3; ++c) {
    const char* ch[3] = {"r", "g", "b"};
    material.add(std::string("sigma_a_") + ch[c], m.sigmaA[c]);
    material.add(std::string("sigma_s_prime_") + ch[c], m.sigmaSPrime[c]);
  }
  JsonObject stats;
  stats.add("method", t.name)
      .add("knobs", knobJson)
      .add("mesh", scene.meshName)
      .add("triangles", double(scene.mesh.triangles.size()))
      .add("size_mm", scene.sizeMm)
      .add("material", material)
      .raw("lights", jsonStrings(scene.lightDescriptions))
      .add("width", double(scene.camera.width))
      .add("height", double(scene.camera.height))
      .add("wall_seconds", run.seconds)
      .add("peak_memory_mib", peakMemoryMiB())
      .add("sample_unit", run.stats.sampleUnit)
      .add("figures", figures)
      .raw("warnings", jsonStrings(run.stats.warnings));
  return stats.str() + "\n";
}
/// The planner's technique and knobs for the scene (render --method auto).
std::pair<const technique::Technique*, technique::KnobValues> plannedTechnique(
    const Args& args, const Scene& scene, const technique::ShadeRequest& pixels,
    const plan::Budget& budget) {
  const plan::Plan p = planScene(args, scene, pixels, budget);
  enforceHardLimit(p, budget);
  if (!p.choice)
    throw InputError(std::string("lucent render: ") +
                     (args.has("method") ? "--method auto"
                                         : "no --method, and the default cannot take the scene") +
                     ": no calibrated technique can serve this scene (lucent plan --explain says "
                     "why); name a --method that takes it (lucent techniques lists what each can)");
  std::fprintf(stderr, "lucent render: auto: %s\n", plan::candidateLine(*p.choice).c_str());
  if (!p.meetsBudget)
    std::fprintf(stderr,
                 "lucent render: warning: no calibrated setting meets the budget (%s); this is "
                 "the closest. Give --hard-limit to refuse instead\n",
                 plan::budgetText(budget).c_str());
  for (const auto& o : p.outsideCalibration)
    std::fprintf(stderr, "lucent render: warning: outside the planner's calibration data: %s\n",
                 o.c_str());
  return {p.choice->technique, p.choice->technique->values(plan::knobPairs(p.choice->knobs))};
}
/// With no --method: whether the default technique cannot take the scene (a scan's heterogeneous
/// medium, say), so the planner chooses one that can, as --method auto would. Says so on stderr.
bool defaultCannotServe(const Args& args, const technique::Technique& fallback, const Scene& scene,
                        std::optional<technique::ShadeRequest>& pixels) {
  pixels = technique::pixelRequest(scene.camera, scene);
  const auto missing = technique::unmetBy(fallback, scene, *pixels);
  if (missing.empty()) return false;
  if (args.has("knob"))
    args.fail("the default technique '" + fallback.name + "' cannot take " + missing.front() +
              ": name a --method for the --knob, or drop --knob and let the planner choose");
  std::fprintf(stderr,
               "lucent render: no --method: the default '%s' cannot take %s; the planner "
               "chooses one that can (as --method auto)\n",
               fallback.name.c_str(), missing.front().c_str());
  return true;
}
}  // namespace

int runRender(int argc, char** argv) {
  const technique::Registry& registry = technique::appRegistry();
  std::vector<OptionSpec> specs = sceneOptionSpecs();
  for (auto& s : toneMapOptionSpecs()) specs.push_back(s);
  specs.push_back({"method", "NAME|auto",
                   "rendering technique (default " + registry.defaultReference().name +
                       ", or the planner's choice where it cannot take the scene); auto: the "
                       "planner's choice for the scene and budget (lucent plan)"});
  for (auto& s : planOptionSpecs()) specs.push_back(s);
  specs.push_back({"knob", "NAME=VALUE", "set one of the method's knobs", true});
  specs.push_back({"out", "FILE",
                   "output image: .exr (linear radiance, alpha = coverage) or .png (tone-mapped)",
                   true});
  specs.push_back(
      {"stats", "FILE.json", "write wall time, peak memory, sample counts and every knob as JSON"});
  specs.push_back({"quiet", "", "no progress bars"});
  Args args(
      "render",
      "lucent render [--mesh FILE | --shape NAME] [--material NAME] [--light SPEC]... --out FILE",
      specs);
  args.parse(argc, argv, 2);
  if (args.helpRequested()) {
    std::cout << args.helpText() << techniqueHelp(registry);
    return 0;
  }
  if (!args.positional().empty())
    args.fail("unexpected argument '" + args.positional().front() + "'");
  const std::vector<std::string> outputs = args.all("out");
  if (outputs.empty()) args.fail("no output: give --out FILE.exr or --out FILE.png");
  const image::ToneMap toneMap = toneMapFromArgs(args);
  for (const auto& o : outputs)
    if (!isExr(o) && !isPng(o)) args.fail("--out '" + o + "': use a .exr or .png file name");

  bool automatic = args.get("method") == plan::kAutomatic;
  const plan::Budget budget = budgetOf(args);
  if (!automatic && (budget.given() || args.has("calibration")))
    args.fail("--budget-ms, --max-error and --calibration go with --method auto");
  if (automatic && args.has("knob"))
    args.fail("--method auto chooses the knobs: drop --knob, or name a method");
  const technique::Technique* chosen =
      automatic ? nullptr : &techniqueArg(registry, args, "method");
  technique::KnobValues knobs =
      automatic ? technique::KnobValues() : chosen->values(knobArgs(args, "knob"));
  // Every output is checked before any work: nothing is written unless everything can be.
  std::vector<NamedOutput> written = knobOutputs({knobs});
  for (const auto& o : outputs) written.push_back({"--out", o});
  if (args.has("stats")) written.push_back({"--stats", args.get("stats")});
  checkOutputs(args, written, sceneInputFiles(args));

  Scene scene = buildScene(args);
  // The plan reads the pixels the camera sees; the render takes the same ones.
  std::optional<technique::ShadeRequest> pixels;
  if (!args.has("method")) automatic = defaultCannotServe(args, *chosen, scene, pixels);
  if (automatic) {
    if (!pixels) pixels = technique::pixelRequest(scene.camera, scene);
    std::tie(chosen, knobs) = plannedTechnique(args, scene, *pixels, budget);
  }
  const technique::Technique& technique = *chosen;
  const ImageRun run = renderImage(registry, technique, scene, knobs, !args.has("quiet"),
                                   pixels ? &*pixels : nullptr);
  for (const auto& note : run.stats.warnings)
    std::fprintf(stderr, "lucent render: warning: %s\n", note.c_str());
  if (scene.medium.heterogeneous())
    std::fprintf(stderr, "lucent render: density: %s\n", scene.medium.densityDescription.c_str());
  for (const auto& inc : scene.inclusions)
    std::fprintf(stderr, "lucent render: inclusion: %s\n", inc.description.c_str());
  for (const auto& o : outputs) writeImage(o, run.image, toneMap);
  if (args.has("stats"))
    io::writeTextFile(args.get("stats"), statsJson(scene, technique, knobs, run));
  std::fprintf(stderr, "lucent render: %s in %.2f s\n", technique.name.c_str(), run.seconds);
  return 0;
}

}  // namespace lucent::cli
