// libFuzzer target: an OpenEXR file as the environment reader reads it.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.hpp"
#include "io/exr_io.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = lucent::fuzz::writeInput(data, size, ".exr");
  try {
    const lucent::image::Image img = lucent::io::readExr(path);
    if (img.pixels.size() != std::size_t(img.width) * std::size_t(img.height)) __builtin_trap();
  } catch (const lucent::InputError&) {
  }
  return 0;
}
