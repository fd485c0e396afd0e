#pragma once
// The fuzz input as a file of a given extension, for readers that take a path (VTK's, OpenEXR's,
// lucent's).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

namespace lucent::fuzz {

inline std::string writeInput(const std::uint8_t* data, std::size_t size,
                              const std::string& extension) {
  const std::string path = "/tmp/lucent-fuzz-" + std::to_string(::getpid()) + extension;
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

}  // namespace lucent::fuzz
