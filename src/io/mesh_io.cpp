#include "mesh_io.hpp"
#include <cstdio>

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include "../util/error.hpp"
#include "mesh_file_checks.hpp"
#include "off_reader.hpp"
#include "ply_reader.hpp"
#include "quiet_vtk.hpp"
#include "stl_reader.hpp"
#include "vtk_mesh.hpp"

namespace lucent::io {

namespace {
template <class Reader>
vtkSmartPointer<vtkPolyData> readWith(const std::string& path) {
  const QuietVtk quiet;
  auto reader = vtkSmartPointer<Reader>::New();
  std::string problem;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetClientData(&problem);
  onError->SetCallback([](vtkObject*, unsigned long, void* sink, void* message) {
    auto& text = *static_cast<std::string*>(sink);
    if (text.empty() && message) text = static_cast<const char*>(message);
  });
  reader->AddObserver(vtkCommand::ErrorEvent, onError);
  reader->SetFileName(path.c_str());
  reader->Update();
  if (!problem.empty()) {
    while (!problem.empty() && (problem.back() == '\n' || problem.back() == ' '))
      problem.pop_back();
    const auto colon = problem.rfind(": ");
    throw InputError("cannot read mesh '" + path + "': the reader failed (" +
                     (colon == std::string::npos ? problem : problem.substr(colon + 2)) +
                     "); is the file complete and a valid mesh?");
  }
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
    pd = readPly(path);  // lucent's own: VTK's PLY reader cannot be made safe
  else if (ext == ".obj")
    pd = readObj(path);  // lucent's own: VTK's OBJ reader cannot be made safe
  else if (ext == ".stl")
    pd = readStl(path);  // lucent's own: VTK's STL reader trusts the triangle count
  else if (ext == ".off")
    pd = readOff(path);  // VTK 9.1 has no OFF reader
  else if (ext == ".vtp")
    pd = readWith<vtkXMLPolyDataReader>(path);
  else if (ext == ".vtk")
    pd = readWith<vtkPolyDataReader>(path);
  else
    throw InputError("cannot read mesh '" + path + "': unknown extension '" + ext +
                     "'; use .ply, .obj, .stl, .off, .vtp or .vtk (legacy polydata)");
  if (!pd || pd->GetNumberOfPoints() == 0)
    throw InputError("cannot read mesh '" + path +
                     "': the reader found no points; is the file a valid " + ext + " mesh?");
  checkPolyData(pd, path);
  bool flipped = false;
  std::size_t missing = 0;
  scene::TriangleMesh mesh = fromPolyData(pd, &flipped, &missing);
  if (missing > 0)
    std::fprintf(stderr,
                 "lucent: note: mesh '%s': %zu triangles are missing where non-convex polygons "
                 "could not be triangulated (non-planar, self-overlapping or degenerate); "
                 "their edges show as holes: triangulate the mesh in its modeller\n",
                 path.c_str(), missing);
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
