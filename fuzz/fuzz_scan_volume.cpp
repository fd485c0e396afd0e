// libFuzzer target: a scan as `--volume` reads it (lucent's header check, then VTK's reader), in
// the format LUCENT_FUZZ_EXTENSION names: .nrrd, .mha, .nii, .nii.gz, .vtk; or "dicom": the input
// split at each "LUCENTSLICE" into the files of a folder. Bad input must be an InputError.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz_input_file.hpp"
#include "io/vtk_volume.hpp"
#include "util/error.hpp"

namespace {
/// A folder holding the input's parts, one file each (at most 8).
std::string writeFolder(const std::uint8_t* data, std::size_t size) {
  const std::string folder = "/tmp/lucent-fuzz-dicom-" + std::to_string(::getpid());
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const std::string input(reinterpret_cast<const char*>(data), size), separator = "LUCENTSLICE";
  std::size_t begin = 0;
  for (int part = 0; part < 8 && begin <= input.size(); ++part) {
    auto end = input.find(separator, begin);
    if (end == std::string::npos || part == 7) end = input.size();
    std::ofstream(folder + "/slice" + std::to_string(part), std::ios::binary)
        .write(input.data() + begin, std::streamsize(end - begin));
    begin = end + separator.size();
  }
  return folder;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string extension = LUCENT_FUZZ_EXTENSION;
  const std::string path = extension == "dicom" ? writeFolder(data, size)
                                                : lucent::fuzz::writeInput(data, size, extension);
  try {
    const auto grid = lucent::io::readImageVolume(path);
    if (grid.values.size() != std::size_t(grid.dims.x) * grid.dims.y * grid.dims.z)
      __builtin_trap();  // a grid whose values disagree with its size
  } catch (const lucent::InputError&) {
  }
  return 0;
}
