#include "mesh_file_checks.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include "../util/error.hpp"

namespace lucent::io {

namespace {
[[noreturn]] void fail(const std::string& path, const std::string& problem,
                       const std::string& fix) {
  throw InputError("cannot read mesh '" + path + "': " + problem + "; " + fix);
}

/// One OBJ face corner "i", "i/t", "i//n" or "i/t/n": the vertex index i.
long long objVertexIndex(const std::string& corner, const std::string& path, std::size_t line) {
  const std::string head = corner.substr(0, corner.find('/'));
  char* end = nullptr;
  const long long i = std::strtoll(head.c_str(), &end, 10);
  if (head.empty() || *end != '\0')
    fail(path,
         "line " + std::to_string(line) + ": face corner '" + corner + "' is not a vertex index",
         "write faces as f i j k with vertex numbers");
  return i;
}
}  // namespace

void checkObjFile(const std::string& path) {
  std::ifstream in(path);
  std::string text;
  std::size_t line = 0;
  long long vertices = 0;
  std::uint64_t faces = 0;
  while (std::getline(in, text)) {
    ++line;
    std::istringstream words(text);
    std::string kind;
    words >> kind;
    if (kind == "v") {
      double c[3];
      for (double& x : c) {
        std::string w;
        words >> w;
        char* end = nullptr;
        x = std::strtod(w.c_str(), &end);
        if (w.empty() || *end != '\0' || !std::isfinite(x))
          fail(path,
               "line " + std::to_string(line) + ": vertex " + std::to_string(vertices + 1) +
                   " has a coordinate that is not a finite number ('" + w + "')",
               "fix or remove that vertex");
      }
      if (++vertices > static_cast<long long>(kMaxMeshPoints))
        fail(path, "more than " + std::to_string(kMaxMeshPoints) + " vertices",
             "decimate the mesh first");
    } else if (kind == "f") {
      std::string corner;
      int corners = 0;
      while (words >> corner) {
        const long long i = objVertexIndex(corner, path, line);
        const long long resolved = i < 0 ? vertices + 1 + i : i;
        if (i == 0 || resolved < 1 || resolved > vertices)
          fail(path,
               "line " + std::to_string(line) + ": face " + std::to_string(faces + 1) +
                   " names vertex " + std::to_string(i) + ", but " + std::to_string(vertices) +
                   " vertices are defined before it",
               "vertex numbers start at 1 (negative ones count back from the last vertex); "
               "re-export the mesh");
        ++corners;
      }
      if (corners < 3)
        fail(path,
             "line " + std::to_string(line) + ": a face with " + std::to_string(corners) +
                 " corners",
             "every face needs at least 3");
      if (++faces > kMaxMeshFaces)
        fail(path, "more than " + std::to_string(kMaxMeshFaces) + " faces",
             "decimate the mesh first");
    }
  }
}

namespace {
struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::uint64_t minBytes = 0;  ///< the fewest bytes one element can take in this format
};

/// Bytes of a PLY scalar type, 0 when unknown.
int plyTypeSize(const std::string& t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32")
    return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}
}  // namespace

void checkPlyFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string text;
  if (!std::getline(in, text) || text.rfind("ply", 0) != 0)
    fail(path, "it does not start with 'ply'", "is it a PLY file?");
  bool ascii = false, ended = false;
  std::vector<PlyElement> elements;
  while (std::getline(in, text)) {
    if (!text.empty() && text.back() == '\r') text.pop_back();
    std::istringstream words(text);
    std::string key;
    words >> key;
    if (key == "end_header") {
      ended = true;
      break;
    }
    if (key == "format") {
      std::string format;
      words >> format;
      ascii = format == "ascii";
    } else if (key == "element") {
      PlyElement e;
      std::string count;
      words >> e.name >> count;
      char* end = nullptr;
      const double n = std::strtod(count.c_str(), &end);
      if (count.empty() || *end != '\0' || !(n >= 0) || n != std::floor(n))
        fail(path, "the header's element '" + e.name + "' has the count '" + count + "'",
             "it must be a whole number");
      const std::uint64_t bound = e.name == "vertex" ? kMaxMeshPoints : kMaxMeshFaces;
      if (n > double(bound))
        fail(path,
             "the header declares " + count + " " + e.name + " elements, more than lucent reads (" +
                 std::to_string(bound) + ")",
             "decimate the mesh first");
      e.count = std::uint64_t(n);
      elements.push_back(e);
    } else if (key == "property" && !elements.empty()) {
      std::string type;
      words >> type;
      if (type == "list") {
        std::string countType;
        words >> countType;
        elements.back().minBytes += ascii ? 2 : std::uint64_t(std::max(plyTypeSize(countType), 1));
      } else {
        elements.back().minBytes += ascii ? 2 : std::uint64_t(std::max(plyTypeSize(type), 1));
      }
    }
  }
  if (!ended)
    fail(path, "the header has no end_header line", "the file is truncated or not a PLY file");
  const auto headerBytes = std::uint64_t(in.tellg());
  const auto fileBytes = std::uint64_t(std::filesystem::file_size(path));
  std::uint64_t need = 0;
  for (const auto& e : elements) need += e.count * e.minBytes;
  if (fileBytes - headerBytes < need) {
    std::string declared;
    for (const auto& e : elements)
      declared += (declared.empty() ? "" : " and ") + std::to_string(e.count) + " " + e.name;
    fail(path,
         "its header declares " + declared + " elements, which take at least " +
             std::to_string(need) + " bytes, but only " + std::to_string(fileBytes - headerBytes) +
             " follow the header",
         "the file is truncated or its header is wrong; re-export it");
  }
}

void checkPolyData(vtkPolyData* data, const std::string& path) {
  const vtkIdType points = data->GetNumberOfPoints();
  for (vtkIdType i = 0; i < points; ++i) {
    double p[3];
    data->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      fail(path, "point " + std::to_string(i) + " has a coordinate that is not a finite number",
           "fix or remove that vertex");
  }
  for (vtkCellArray* cells :
       {data->GetVerts(), data->GetLines(), data->GetPolys(), data->GetStrips()}) {
    if (!cells) continue;
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    for (cells->InitTraversal(); cells->GetNextCell(n, ids);)
      for (vtkIdType k = 0; k < n; ++k)
        if (ids[k] < 0 || ids[k] >= points)
          fail(path,
               "a cell names point " + std::to_string(ids[k]) + " of " + std::to_string(points),
               "the file's indices are out of range; re-export it");
  }
}

}  // namespace lucent::io
