#pragma once
/// @file mesh_file_checks.hpp
/// @brief What lucent checks in a mesh file before VTK's readers see it, and in what they return:
/// VTK's OBJ and PLY readers trust the file (an out-of-range face index crashes, a PLY header that
/// declares 10^7 faces in a tiny file aborts with a double free, one declaring 10^9 vertices prints
/// a line per missing vertex). Each check throws InputError naming the file, the problem and the
/// fix.
#include <cstdint>
#include <string>

class vtkPolyData;

namespace lucent::io {

/// The most points and faces a mesh file may declare: a bound on what reading it allocates (about
/// 40 and 60 bytes each once read, so 10^8 points and 2 x 10^8 faces take about 16 GB).
inline constexpr std::uint64_t kMaxMeshPoints = 100'000'000;
inline constexpr std::uint64_t kMaxMeshFaces = 200'000'000;

/// OBJ: every face index names an existing vertex (1-based, or negative counting back), none is 0,
/// and every coordinate is a finite number.
void checkObjFile(const std::string& path);

/// PLY: a well-formed header whose element counts are within bounds and fit in the file's size.
void checkPlyFile(const std::string& path);

/// Any reader's output: finite coordinates, and every cell's point ids in range.
void checkPolyData(vtkPolyData* data, const std::string& path);

}  // namespace lucent::io
