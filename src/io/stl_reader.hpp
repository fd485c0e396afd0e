#pragma once
/// @file stl_reader.hpp
/// @brief STL meshes read by lucent itself: VTK's reader trusts a binary file's triangle count (a
/// 100-byte file declaring 2^31 triangles makes it allocate tens of GB; found by
/// fuzz/fuzz_mesh.cpp), and reads a truncated file as a mesh with holes. ASCII (one or more solids)
/// and binary. Coincident corners are welded exactly, as VTK's reader does, so a closed STL is a
/// closed mesh.
#include <string>

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace lucent::io {

/// Throws InputError naming the file, the problem and the fix: a binary file whose size does not
/// match its triangle count (truncated or corrupt), an ASCII file that ends inside a facet or lacks
/// `endsolid`, a word where a keyword or a number belongs, a coordinate that is not finite or
/// beyond kMaxCoordinate, more than kMaxMeshFaces triangles.
vtkSmartPointer<vtkPolyData> readStl(const std::string& path);

}  // namespace lucent::io
