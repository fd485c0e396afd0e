#pragma once
/// @file mesh_io.hpp
/// @brief Reads meshes with VTK's readers: .ply, .obj, .stl, .off, .vtp, .vtk (legacy polydata).
#include <string>

#include <lucent/scene/mesh.hpp>

namespace lucent::io {

/// Throws InputError naming the file, the problem and the fix (unknown extension, missing or unreadable
/// file, no triangles).
scene::TriangleMesh readMesh(const std::string& path);

}  // namespace lucent::io
