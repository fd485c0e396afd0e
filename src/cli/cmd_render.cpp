/// `lucent render`: renders a scene with one method and writes EXR/PNG images and a JSON stats file.
#include <cstdio>
#include <iostream>

#include "../io/atomic_file.hpp"
#include "../render/methods.hpp"
#include "../util/error.hpp"
#include "commands.hpp"
#include "image_output.hpp"
#include "json_writer.hpp"
#include "process_stats.hpp"

namespace lucent::cli {

namespace {
std::string methodHelp() {
  std::string s = "\nmethods and their knobs (--knob NAME=VALUE):\n";
  for (const auto& m : render::methods()) {
    s += "  " + m.name + ": " + m.summary + "\n";
    for (const auto& k : m.knobs) s += "      " + k.name + " (default " + k.defaultValue + "): " + k.help + "\n";
  }
  return s;
}

}  // namespace

int runRender(int argc, char** argv) {
  std::vector<OptionSpec> specs = sceneOptionSpecs();
  for (auto& s : toneMapOptionSpecs()) specs.push_back(s);
  specs.push_back({"method", "NAME", "rendering technique (default reference)"});
  specs.push_back({"knob", "NAME=VALUE", "set one of the method's knobs", true});
  specs.push_back({"spp", "N", "samples per pixel (the knob spp of pathtrace, the Monte Carlo method)"});
  specs.push_back({"out", "FILE", "output image: .exr (linear radiance, alpha = coverage) or .png (tone-mapped)", true});
  specs.push_back({"stats", "FILE.json", "write wall time, peak memory, sample counts and every knob as JSON"});
  specs.push_back({"quiet", "", "no progress bars"});
  Args args("render", "lucent render [--mesh FILE | --shape NAME] [--material NAME] [--light SPEC]... --out FILE", specs);
  args.parse(argc, argv, 2);
  if (args.helpRequested()) {
    std::cout << args.helpText() << methodHelp();
    return 0;
  }
  if (!args.positional().empty()) args.fail("unexpected argument '" + args.positional().front() + "'");
  const std::vector<std::string> outputs = args.all("out");
  if (outputs.empty()) args.fail("no output: give --out FILE.exr or --out FILE.png");
  const image::ToneMap toneMap = toneMapFromArgs(args);
  for (const auto& o : outputs)
    if (!isExr(o) && !isPng(o))
      args.fail("--out '" + o + "': use a .exr or .png file name");

  const render::Method& method = render::findMethod(args.get("method", "reference"));
  std::map<std::string, std::string> given;
  for (const auto& k : args.all("knob"))
    for (const auto& [name, value] : render::parseKnobList(k)) given[name] = value;
  if (args.has("spp")) given["spp"] = args.get("spp", "");
  const render::Knobs knobs(method.knobs, given, method.name);

  const Scene scene = buildScene(args);
  const bool progress = !args.has("quiet");
  render::RenderResult result = method.run(scene, knobs, progress);
  for (const auto& note : result.notes) std::fprintf(stderr, "lucent render: warning: %s\n", note.c_str());
  for (const auto& o : outputs) writeImage(o, result.image, toneMap);

  if (args.has("stats")) {
    JsonObject knobJson, figures, material;
    for (const auto& [k, v] : knobs.values()) knobJson.add(k, v);
    for (const auto& [k, v] : result.figures) figures.add(k, v);
    material.add("name", scene.material.name).add("eta", scene.material.eta);
    for (int c = 0; c < 3; ++c) {
      const char* ch[3] = {"r", "g", "b"};
      material.add(std::string("sigma_a_") + ch[c], scene.material.sigmaA[c]);
      material.add(std::string("sigma_s_prime_") + ch[c], scene.material.sigmaSPrime[c]);
    }
    std::string lights = "[";
    for (std::size_t i = 0; i < scene.lightDescriptions.size(); ++i)
      lights += (i ? ", " : "") + JsonObject::quote(scene.lightDescriptions[i]);
    lights += "]";
    std::string notes = "[";
    for (std::size_t i = 0; i < result.notes.size(); ++i) notes += (i ? ", " : "") + JsonObject::quote(result.notes[i]);
    notes += "]";
    JsonObject stats;
    stats.add("method", method.name)
        .add("knobs", knobJson)
        .add("mesh", scene.meshName)
        .add("triangles", double(scene.mesh.triangles.size()))
        .add("size_mm", scene.sizeMm)
        .add("material", material)
        .raw("lights", lights)
        .add("width", double(scene.camera.width))
        .add("height", double(scene.camera.height))
        .add("wall_seconds", result.seconds)
        .add("peak_memory_mib", peakMemoryMiB())
        .add("figures", figures)
        .raw("warnings", notes);
    io::writeTextFile(args.get("stats"), stats.str() + "\n");
  }
  std::fprintf(stderr, "lucent render: %s in %.2f s\n", method.name.c_str(), result.seconds);
  return 0;
}

}  // namespace lucent::cli
