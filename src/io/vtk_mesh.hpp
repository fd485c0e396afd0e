#pragma once
/// @file vtk_mesh.hpp
/// @brief Conversions between lucent's TriangleMesh and vtkPolyData.
#include <vtkSmartPointer.h>

#include <lucent/scene/mesh.hpp>

class vtkPolyData;

namespace lucent::io {

/// Triangulates polygons and strips, merges coincident points, drops lines and vertices.
scene::TriangleMesh fromPolyData(vtkPolyData* polyData);
vtkSmartPointer<vtkPolyData> toPolyData(const scene::TriangleMesh& mesh);

}  // namespace lucent::io
