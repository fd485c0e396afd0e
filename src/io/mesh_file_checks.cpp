#include "mesh_file_checks.hpp"

#include <cmath>
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

namespace lucent::io {

namespace {
[[noreturn]] void fail(const std::string& path, const std::string& problem,
                       const std::string& fix) {
  throw InputError("cannot read mesh '" + path + "': " + problem + "; " + fix);
}

/// Counts of what an OBJ file has defined so far, by the line kind that defines it.
struct ObjCounts {
  long long v = 0, vt = 0, vn = 0;
  std::uint64_t faces = 0;
};

/// A line's numbers after its keyword: `least` to `most` of them, each finite and at most
/// kMaxCoordinate.
std::vector<double> checkObjNumbers(std::istringstream& words, int least, int most,
                                    const std::string& what, const std::string& path,
                                    std::size_t line) {
  std::vector<double> values;
  int count = 0;
  for (std::string w; words >> w;) {
    char* end = nullptr;
    const double x = std::strtod(w.c_str(), &end);
    if (*end != '\0' || !(std::abs(x) <= kMaxCoordinate))
      fail(path,
           "line " + std::to_string(line) + ": " + what + " has '" + w +
               "', not a finite number of at most 1e30",
           "fix or remove that line");
    values.push_back(x);
    ++count;
  }
  if (count < least || count > most)
    fail(
        path,
        "line " + std::to_string(line) + ": " + what + " has " + std::to_string(count) + " numbers",
        "a vertex needs 3 (4, or 6 to 7 with colour), a normal 3, a texture coordinate 1 to 3");
  return values;
}

/// One index of a face corner "i", "i/t", "i//n" or "i/t/n" (empty = not given), within the
/// `defined` so far.
long long checkObjIndex(const std::string& text, long long defined, const char* of,
                        const std::string& corner, const std::string& path, std::size_t line) {
  char* end = nullptr;
  const long long i = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0')
    fail(path,
         "line " + std::to_string(line) + ": face corner '" + corner + "' has '" + text +
             "', not an index",
         "write faces as f v, f v/t, f v//n or f v/t/n with whole numbers");
  const long long resolved = i < 0 ? defined + 1 + i : i;
  if (i == 0 || resolved < 1 || resolved > defined)
    fail(path,
         "line " + std::to_string(line) + ": face corner '" + corner + "' names " + of + " " +
             std::to_string(i) + ", but " + std::to_string(defined) + " are defined before it",
         "numbers start at 1 (negative ones count back from the last); re-export the mesh");
  return resolved - 1;  // 0-based
}

std::vector<vtkIdType> checkObjFace(std::istringstream& words, ObjCounts& n,
                                    const std::string& path, std::size_t line) {
  std::vector<vtkIdType> ids;
  int corners = 0;
  for (std::string corner; words >> corner; ++corners) {
    if (corners == kMaxFaceCorners)  // triangulating a polygon is quadratic in its corners
      fail(path,
           "line " + std::to_string(line) + ": a face with more than " +
               std::to_string(kMaxFaceCorners) + " corners",
           "split it into smaller faces");
    const auto slash1 = corner.find('/');
    ids.push_back(
        vtkIdType(checkObjIndex(corner.substr(0, slash1), n.v, "vertex", corner, path, line)));
    if (slash1 == std::string::npos) continue;
    const auto slash2 = corner.find('/', slash1 + 1);
    const std::string t = corner.substr(
        slash1 + 1, slash2 == std::string::npos ? std::string::npos : slash2 - slash1 - 1);
    if (!t.empty()) checkObjIndex(t, n.vt, "texture coordinate", corner, path, line);
    if (slash2 != std::string::npos)
      checkObjIndex(corner.substr(slash2 + 1), n.vn, "normal", corner, path, line);
  }
  if (corners < 3)
    fail(path,
         "line " + std::to_string(line) + ": a face with " + std::to_string(corners) + " corners",
         "every face needs at least 3");
  if (++n.faces > kMaxMeshFaces)
    fail(path, "more than " + std::to_string(kMaxMeshFaces) + " faces", "decimate the mesh first");
  return ids;
}
}  // namespace

vtkSmartPointer<vtkPolyData> readObj(const std::string& path) {
  std::ifstream in(path);
  std::string text;
  std::size_t line = 0;
  ObjCounts n;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  while (std::getline(in, text)) {
    ++line;
    std::istringstream words(text);
    std::string kind;
    words >> kind;
    if (kind == "v") {
      const auto xyz =
          checkObjNumbers(words, 3, 7, "vertex " + std::to_string(n.v + 1), path, line);
      if (++n.v > static_cast<long long>(kMaxMeshPoints))
        fail(path, "more than " + std::to_string(kMaxMeshPoints) + " vertices",
             "decimate the mesh first");
      points->InsertNextPoint(xyz[0], xyz[1], xyz[2]);
    } else if (kind == "vt") {
      checkObjNumbers(words, 1, 3, "texture coordinate " + std::to_string(++n.vt), path, line);
    } else if (kind == "vn") {
      checkObjNumbers(words, 3, 3, "normal " + std::to_string(++n.vn), path, line);
    } else if (kind == "f") {
      const std::vector<vtkIdType> ids = checkObjFace(words, n, path, line);
      polys->InsertNextCell(vtkIdType(ids.size()), ids.data());
    }
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(polys);
  return out;
}

void checkPolyData(vtkPolyData* data, const std::string& path) {
  const vtkIdType points = data->GetNumberOfPoints();
  for (vtkIdType i = 0; i < points; ++i) {
    double p[3];
    data->GetPoint(i, p);
    if (!(std::abs(p[0]) <= kMaxCoordinate && std::abs(p[1]) <= kMaxCoordinate &&
          std::abs(p[2]) <= kMaxCoordinate))
      fail(path,
           "point " + std::to_string(i) +
               " has a coordinate that is not a finite number of at most 1e30",
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
