#include "material_options.hpp"

namespace lucent::cli {

std::vector<OptionSpec> materialOptionSpecs() {
  return {{"material", "NAME", "measured material; see 'lucent materials'"},
          {"sigma-a", "R,G,B", "custom absorption coefficient (mm^-1)"},
          {"sigma-s", "R,G,B", "custom reduced scattering coefficient sigma_s' (mm^-1)"},
          {"eta", "X", "relative index of refraction, in [1, 3]"}};
}

optics::Material materialFromArgs(const Args& args, const char* fallbackName) {
  const bool custom = args.has("sigma-a") || args.has("sigma-s");
  if (custom && args.has("material")) args.fail("give either --material or --sigma-a/--sigma-s, not both");
  optics::Material m;
  if (custom) {
    if (!args.has("sigma-a") || !args.has("sigma-s")) args.fail("a custom material needs both --sigma-a and --sigma-s");
    m.name = "custom";
    m.sigmaA = args.triple("sigma-a", glm::dvec3(0));
    m.sigmaSPrime = args.triple("sigma-s", glm::dvec3(0));
    m.source = "user";
  } else {
    const std::string name = args.get("material", fallbackName);
    const auto found = optics::findMaterial(name);
    if (!found) args.fail("unknown material '" + name + "'; run 'lucent materials' for the list");
    m = *found;
  }
  if (args.has("eta")) m.eta = args.number("eta", m.eta, -1e300, 1e300);
  if (const std::string why = optics::validateMaterial(m); !why.empty()) args.fail("material '" + m.name + "': " + why);
  return m;
}

}  // namespace lucent::cli
