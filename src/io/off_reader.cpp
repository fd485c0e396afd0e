#include "off_reader.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include "../util/error.hpp"
#include "mesh_file_checks.hpp"

namespace lucent::io {

namespace {
[[noreturn]] void fail(const std::string& path, std::size_t line, const std::string& problem,
                       const std::string& fix) {
  throw InputError("cannot read mesh '" + path +
                   "': " + (line ? "line " + std::to_string(line) + ": " : std::string()) +
                   problem + "; " + fix);
}

/// The file's lines with their comments cut and blank ones skipped, numbered as in the file.
struct OffLines {
  std::ifstream in;
  std::size_t number = 0;
  bool next(std::istringstream& words) {
    for (std::string text; std::getline(in, text);) {
      ++number;
      const auto hash = text.find('#');
      if (hash != std::string::npos) text.erase(hash);
      if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
      words.clear();
      words.str(text);
      return true;
    }
    return false;
  }
  /// The line of item `i` of `n` (`what`: "vertices", "faces"), or the error that the file ends.
  void require(std::istringstream& words, std::uint64_t i, std::uint64_t n, const char* what,
               const std::string& path) {
    if (!next(words))
      fail(path, number,
           "the file ends after " + std::to_string(i) + " of " + std::to_string(n) + " " + what,
           "the file is truncated; re-export it");
  }
};

/// A whole number of at most `most` from `words`, or the error naming `what` with `fix` (for a
/// number too large: `tooLarge`).
std::uint64_t count(std::istringstream& words, std::uint64_t most, const std::string& what,
                    const std::string& path, std::size_t line,
                    const char* fix = "the line after OFF gives the vertex, face and edge counts",
                    const char* tooLarge = "decimate the mesh first") {
  std::string w;
  words >> w;
  char* end = nullptr;
  const long long v = std::strtoll(w.c_str(), &end, 10);
  if (w.empty() || *end != '\0' || v < 0)
    fail(path, line, what + " is '" + w + "', not a whole number", fix);
  if (std::uint64_t(v) > most)
    fail(path, line, what + " is " + w + ", more than " + std::to_string(most), tooLarge);
  return std::uint64_t(v);
}

double coordinate(std::istringstream& words, const std::string& path, std::size_t line) {
  std::string w;
  words >> w;
  char* end = nullptr;
  const double x = std::strtod(w.c_str(), &end);
  if (w.empty() || *end != '\0' || !(std::abs(x) <= kMaxCoordinate))
    fail(path, line, "a vertex has '" + w + "', not a finite number of at most 1e30",
         "each vertex line starts with x y z");
  return x;
}

/// The counts line, after the optional keyword (which may share its line with the counts).
std::array<std::uint64_t, 2> readHeader(OffLines& lines, const std::string& path) {
  std::istringstream words;
  if (!lines.next(words)) fail(path, 0, "the file is empty", "give an OFF mesh");
  std::string first;
  words >> first;
  const bool keyword = first.size() >= 3 && first.compare(first.size() - 3, 3, "OFF") == 0;
  if (keyword && first.find_first_of("n4") != std::string::npos)
    fail(path, lines.number, "'" + first + "' is a 4D or nD OFF file",
         "lucent reads 3D meshes: convert it to a 3D OFF, PLY or OBJ");
  std::string rest;
  std::getline(words, rest);
  if (keyword && rest.find("BINARY") != std::string::npos)
    fail(path, lines.number, "binary OFF is not read", "save it as ASCII OFF, PLY or OBJ");
  if (!keyword) rest = first + " " + rest;  // no keyword: this line holds the counts
  if (rest.find_first_not_of(" \t\r") == std::string::npos) {
    if (!lines.next(words)) fail(path, lines.number, "no counts after OFF", "add them");
  } else {
    words.clear();
    words.str(rest);
  }
  const std::size_t line = lines.number;
  const auto vertices = count(words, kMaxMeshPoints, "the vertex count", path, line);
  const auto faces = count(words, kMaxMeshFaces, "the face count", path, line);
  // Each vertex takes at least 6 bytes ("0 0 0\n") and each face 8: the file must hold them.
  std::error_code sizeError;
  const auto bytes = std::filesystem::file_size(path, sizeError);
  if (sizeError)
    fail(path, 0, "its size cannot be read (" + sizeError.message() + ")", "give a regular file");
  if (vertices * 6 + faces * 8 > bytes)
    fail(path, line,
         "it declares " + std::to_string(vertices) + " vertices and " + std::to_string(faces) +
             " faces, more than its " + std::to_string(bytes) + " bytes can hold",
         "the file is truncated or its counts are wrong; re-export it");
  return {vertices, faces};
}
}  // namespace

vtkSmartPointer<vtkPolyData> readOff(const std::string& path) {
  OffLines lines{std::ifstream(path)};
  const auto [vertexCount, faceCount] = readHeader(lines, path);
  std::istringstream words;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->Allocate(vtkIdType(vertexCount));
  for (std::uint64_t v = 0; v < vertexCount; ++v) {
    lines.require(words, v, vertexCount, "vertices", path);
    const double x = coordinate(words, path, lines.number);
    const double y = coordinate(words, path, lines.number);
    points->InsertNextPoint(x, y, coordinate(words, path, lines.number));
  }
  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> ids;
  for (std::uint64_t f = 0; f < faceCount; ++f) {
    lines.require(words, f, faceCount, "faces", path);
    const char* faceLine = "a face line is N i0 ... i(N-1): whole numbers";
    const auto corners = count(words, kMaxFaceCorners, "a face's corner count", path, lines.number,
                               faceLine, "split the face into smaller ones");
    ids.resize(corners);
    for (auto& id : ids) {
      const auto index = count(words, kMaxMeshPoints, "a face's vertex index", path, lines.number,
                               faceLine, "indices must name a vertex; re-export the mesh");
      if (index >= vertexCount)
        fail(path, lines.number,
             "a face names vertex " + std::to_string(index) + " of " + std::to_string(vertexCount),
             "indices start at 0 and must name a vertex; re-export the mesh");
      id = vtkIdType(index);
    }
    if (corners >= 3) polys->InsertNextCell(vtkIdType(ids.size()), ids.data());
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(polys);
  return out;
}

}  // namespace lucent::io
