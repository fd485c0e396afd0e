#pragma once
/// @file builtin_shapes.hpp
/// @brief The built-in scenes' shapes by name: sphere, torus, double-torus, genus7, cube-cavity, twirl,
/// slab. The implicit ones are contoured with VTK's flying edges.
#include <string>
#include <vector>

#include <lucent/scene/mesh.hpp>

namespace lucent::scene {

const std::vector<std::string>& builtinShapeNames();
/// Throws InputError listing the valid names when `name` is not one.
TriangleMesh makeBuiltinShape(const std::string& name);

}  // namespace lucent::scene
