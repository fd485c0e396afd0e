#pragma once
/// @file ply_reader.hpp
/// @brief PLY meshes read by lucent itself: VTK's reader trusts the file (a face index out of range
/// crashes it, a header declaring 10^7 faces in a tiny file aborts it with a double free, 10^9
/// vertices print a line per missing one). ASCII and binary (either endianness); vertex x, y, z and
/// the face list vertex_indices (or vertex_index); every other element and property is skipped by
/// its declared type.
#include <string>

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace lucent::io {

/// Throws InputError naming the file, the problem and the fix: a malformed or unsupported header,
/// counts beyond kMaxMeshPoints / kMaxMeshFaces or beyond what the file's size can hold, truncated
/// data, a non-finite coordinate, a face index out of range.
vtkSmartPointer<vtkPolyData> readPly(const std::string& path);

}  // namespace lucent::io
