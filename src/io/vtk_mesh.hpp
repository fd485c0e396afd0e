#pragma once
#include <cstddef>
/// @file vtk_mesh.hpp
/// @brief Conversions between lucent's TriangleMesh and vtkPolyData.
#include <vtkSmartPointer.h>

#include <lucent/scene/mesh.hpp>

class vtkPolyData;

namespace lucent::io {

/// Triangulates polygons and strips, welds coincident points, drops lines and vertices, turns an
/// inside-out mesh outward: vtk_plugin/Common/lucentPolyDataMesh.h, shared with the VTK modules.
/// @param flipped set when the mesh was wound inside out and was turned around
/// `missing` (when given) receives the triangles of polygons VTK's triangulation left out.
scene::TriangleMesh fromPolyData(vtkPolyData* polyData, bool* flipped = nullptr,
                                 std::size_t* missing = nullptr);
vtkSmartPointer<vtkPolyData> toPolyData(const scene::TriangleMesh& mesh);

}  // namespace lucent::io
