// libFuzzer target: a volume (.vti or .vdb, by LUCENT_FUZZ_EXTENSION) as the scene's --density
// reads it.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.hpp"
#include "render/density_field.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = lucent::fuzz::writeInput(data, size, LUCENT_FUZZ_EXTENSION);
  lucent::scene::Bounds box;
  box.lo = glm::dvec3(-1), box.hi = glm::dvec3(1);
  try {
    const auto field = lucent::render::parseDensityField("--density", path, box);
    if (field) {
      const double d = field.at(glm::dvec3(0.1, -0.2, 0.3));
      if (!(d >= 0 && d <= 1)) __builtin_trap();  // fields are normalised to [0, 1]
    }
  } catch (const lucent::InputError&) {
  }
  return 0;
}
