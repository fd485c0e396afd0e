#pragma once
/// @file builtin_shapes.hpp
/// @brief The built-in scenes' shapes by name: sphere, torus, double-torus, genus7, cube-cavity,
/// twirl, slab, bottle; and the inner bodies a shape carries (the bottle's liquid). The implicit
/// ones are contoured with VTK's flying edges.
#include <string>
#include <vector>

#include <lucent/scene/mesh.hpp>

namespace lucent::scene {

/// A closed body inside a built-in shape, in the shape's coordinates, filled with another material.
struct InnerBody {
  TriangleMesh surface;
  std::string defaultMaterial;
  std::string description;
};

const std::vector<std::string>& builtinShapeNames();
/// The inner bodies of a built-in shape (none for most).
std::vector<InnerBody> builtinInnerBodies(const std::string& name);
/// Throws InputError listing the valid names when `name` is not one.
TriangleMesh makeBuiltinShape(const std::string& name);

}  // namespace lucent::scene
