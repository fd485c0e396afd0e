#include "mesh_io.hpp"
#include <cstdio>

#include <vtkAlgorithm.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include "../util/error.hpp"
#include "vtk_mesh.hpp"

namespace lucent::io {

namespace {
template <class Reader>
vtkSmartPointer<vtkPolyData> readWith(const std::string& path) {
  auto reader = vtkSmartPointer<Reader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkPolyData> out = reader->GetOutput();
  return out;
}
}  // namespace

scene::TriangleMesh readMesh(const std::string& path) {
  namespace fs = std::filesystem;
  if (!fs::exists(path))
    throw InputError("cannot read mesh '" + path + "': no such file; check the path");
  if (!std::ifstream(path)) throw InputError("cannot read mesh '" + path + "': permission denied");
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  vtkSmartPointer<vtkPolyData> pd;
  if (ext == ".ply")
    pd = readWith<vtkPLYReader>(path);
  else if (ext == ".obj")
    pd = readWith<vtkOBJReader>(path);
  else if (ext == ".stl")
    pd = readWith<vtkSTLReader>(path);
  else if (ext == ".vtp")
    pd = readWith<vtkXMLPolyDataReader>(path);
  else if (ext == ".vtk")
    pd = readWith<vtkPolyDataReader>(path);
  else
    throw InputError("cannot read mesh '" + path + "': unknown extension '" + ext +
                     "'; use .ply, .obj, .stl, .vtp or .vtk (legacy polydata)");
  if (!pd || pd->GetNumberOfPoints() == 0)
    throw InputError("cannot read mesh '" + path +
                     "': the reader found no points; is the file a valid " + ext + " mesh?");
  bool flipped = false;
  scene::TriangleMesh mesh = fromPolyData(pd, &flipped);
  if (mesh.triangles.empty())
    throw InputError("mesh '" + path +
                     "' has no polygons (only points or lines); lucent needs a closed surface");
  if (flipped)
    std::fprintf(stderr,
                 "lucent: note: mesh '%s' is wound inside out (its normals point in); it was "
                 "turned outward\n",
                 path.c_str());
  return mesh;
}

}  // namespace lucent::io
