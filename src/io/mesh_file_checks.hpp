#pragma once
/// @file mesh_file_checks.hpp
/// @brief Mesh files VTK's readers cannot be trusted with, read and checked by lucent: VTK's OBJ
/// reader crashes on an out-of-range face, texture or normal index and corrupts its heap on mixed
/// corner forms (found by fuzz/fuzz_mesh.cpp); PLY is read by ply_reader.hpp. And the check of any
/// reader's output. Each throws InputError naming the file, the problem and the fix.
#include <cstdint>
#include <string>

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace lucent::io {

/// The most points and faces a mesh file may declare: a bound on what reading it allocates (about
/// 40 and 60 bytes each once read, so 10^8 points and 2 x 10^8 faces take about 16 GB).
inline constexpr std::uint64_t kMaxMeshPoints = 100'000'000;
inline constexpr std::uint64_t kMaxMeshFaces = 200'000'000;
/// The largest coordinate a mesh may have (the mesh is kept in float: beyond ~3e38 a value becomes
/// inf).
inline constexpr double kMaxCoordinate = 1e30;
/// The most corners of one face (ear-cut triangulation is quadratic in them).
inline constexpr int kMaxFaceCorners = 1024;

/// OBJ read by lucent itself: every face, texture and normal index names one defined before it
/// (1-based, or negative counting back; never 0), every number is finite, counts are bounded.
/// Vertices and faces (polygons, by their vertex indices) only: lucent computes its own normals.
vtkSmartPointer<vtkPolyData> readObj(const std::string& path);

/// Any reader's output: finite coordinates, and every cell's point ids in range.
void checkPolyData(vtkPolyData* data, const std::string& path);

}  // namespace lucent::io
