#pragma once
/// @file density_field.hpp
/// @brief The scene's density field (`--density`, read by every technique that takes heterogeneous
/// media): a field in [0, 1] that scales sigma_a and sigma_s, fitted to the mesh's box.
#include <functional>
#include <string>

#include <glm/vec3.hpp>

#include <lucent/scene/mesh.hpp>

namespace lucent::render {

struct DensityField {
  std::function<double(const glm::dvec3&)> at;  ///< empty for a homogeneous medium
  std::string description;                      ///< one line for the render notes
  explicit operator bool() const { return bool(at); }
};

/// "" (homogeneous), "noise:F" (a smooth field in [0.1, 1], F periods across the object),
/// "FILE.vdb[:GRID]" (OpenVDB) or "FILE.vti[:ARRAY]" (VTK image data). A file's index box is fitted
/// to `bounds` and its values divided by their maximum. Throws InputError naming `option`, the
/// problem and the fix.
DensityField parseDensityField(const std::string& option, const std::string& spec,
                               const scene::Bounds& bounds);

}  // namespace lucent::render
