// libFuzzer target: the render command's arguments (one per line) through the option parser, the
// knob parser, the registry's technique and knob checks, and the material options: everything the
// CLI decides before it builds a scene. An InputError or RequestError is the expected answer;
// anything else is a finding.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "cli/args.hpp"
#include "cli/material_options.hpp"
#include "cli/scene_setup.hpp"
#include "cli/technique_run.hpp"
#include "technique/techniques.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> words{"lucent", "render"};
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string w; std::getline(lines, w) && words.size() < 64;) words.push_back(w);
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  std::vector<lucent::cli::OptionSpec> specs = lucent::cli::sceneOptionSpecs();
  specs.push_back({"method", "NAME", ""});
  specs.push_back({"knob", "NAME=VALUE", "", true});
  specs.push_back({"out", "FILE", "", true});
  try {
    lucent::cli::Args args("render", "", specs);
    args.parse(int(argv.size()), argv.data(), 2);
    const auto& registry = lucent::technique::appRegistry();
    const auto& technique = lucent::cli::techniqueArg(registry, args, "method");
    technique.values(lucent::cli::knobArgs(args, "knob"));
    lucent::cli::materialFromArgs(args, "skin1");
  } catch (const lucent::InputError&) {
  } catch (const lucent::technique::RequestError&) {
  }
  return 0;
}
