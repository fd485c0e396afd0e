// libFuzzer target: a mesh file (.obj, .ply, .stl or .off, by LUCENT_FUZZ_EXTENSION) through
// lucent's checks and VTK's reader. A clear InputError is the expected answer to bad input; a
// crash, hang or leak is a finding.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.hpp"
#include "io/mesh_io.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = lucent::fuzz::writeInput(data, size, LUCENT_FUZZ_EXTENSION);
  try {
    const lucent::scene::TriangleMesh mesh = lucent::io::readMesh(path);
    for (const auto& t : mesh.triangles)  // what the reader returns is in range
      if (t.x >= mesh.positions.size() || t.y >= mesh.positions.size() ||
          t.z >= mesh.positions.size())
        __builtin_trap();
  } catch (const lucent::InputError&) {
  }
  return 0;
}
