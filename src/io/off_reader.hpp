#pragma once
/// @file off_reader.hpp
/// @brief The Object File Format (.off) of geometry processing (Geomview; CGAL's and many scan
/// archives' meshes), read by lucent itself: VTK 9.1 has no OFF reader.
#include <string>

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace lucent::io {

/// ASCII OFF: an optional `[ST][C][N][4]OFF` keyword, then "vertices faces edges", the vertices
/// (x y z, then normal, colour or texture numbers, ignored) and the faces ("n i0 ... i(n-1)", then
/// an optional colour), with '#' comments anywhere. Counts are checked against kMaxMeshPoints and
/// kMaxMeshFaces and against the file's size before anything is allocated; every index names a
/// vertex, every coordinate is finite. Throws InputError naming the file, the line and the fix;
/// binary OFF and 4D/nD OFF are refused with a fix.
vtkSmartPointer<vtkPolyData> readOff(const std::string& path);

}  // namespace lucent::io
