#include "stl_reader.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <vector>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include "../util/error.hpp"
#include "mesh_file_checks.hpp"

namespace lucent::io {

namespace {
[[noreturn]] void fail(const std::string& path, const std::string& problem,
                       const std::string& fix) {
  throw InputError("cannot read mesh '" + path + "': " + problem + "; " + fix);
}

using Corner = std::array<float, 3>;

/// Triangles with their corners welded where they coincide exactly (an STL repeats every shared
/// corner in each facet).
class WeldedMesh {
 public:
  explicit WeldedMesh(const std::string& path) : mPath(path) {}

  void addTriangle(const std::array<Corner, 3>& corners) {
    if (++mTriangles > kMaxMeshFaces)
      fail(mPath, "more than " + std::to_string(kMaxMeshFaces) + " triangles",
           "decimate the mesh first");
    vtkIdType ids[3];
    for (int c = 0; c < 3; ++c) {
      for (float x : corners[c])
        if (!(std::abs(x) <= kMaxCoordinate))
          fail(mPath,
               "facet " + std::to_string(mTriangles - 1) +
                   " has a coordinate that is not a finite number of at most 1e30",
               "fix or remove that facet");
      const auto [at, added] = mIds.try_emplace(corners[c], mPoints->GetNumberOfPoints());
      if (added) mPoints->InsertNextPoint(corners[c][0], corners[c][1], corners[c][2]);
      ids[c] = at->second;
    }
    if (ids[0] != ids[1] && ids[1] != ids[2] && ids[2] != ids[0])  // welded to a point: no area
      mPolys->InsertNextCell(3, ids);
  }

  std::uint64_t triangles() const { return mTriangles; }

  vtkSmartPointer<vtkPolyData> polyData() const {
    auto out = vtkSmartPointer<vtkPolyData>::New();
    out->SetPoints(mPoints);
    out->SetPolys(mPolys);
    return out;
  }

 private:
  const std::string& mPath;
  std::map<Corner, vtkIdType> mIds;
  vtkNew<vtkPoints> mPoints;
  vtkNew<vtkCellArray> mPolys;
  std::uint64_t mTriangles = 0;
};

constexpr std::uint64_t kBinaryHeader = 84, kBinaryFacet = 50;  // 80-byte header + uint32 count

std::uint32_t littleEndianU32(const unsigned char* b) {
  return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 |
         std::uint32_t(b[3]) << 24;
}

float littleEndianFloat(const unsigned char* b) {
  const std::uint32_t bits = littleEndianU32(b);
  float v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

void readBinary(std::ifstream& in, std::uint64_t count, WeldedMesh& mesh) {
  in.seekg(std::streamoff(kBinaryHeader));
  unsigned char facet[kBinaryFacet];
  for (std::uint64_t i = 0; i < count; ++i) {
    in.read(reinterpret_cast<char*>(facet), sizeof facet);  // size checked: the read cannot fail
    std::array<Corner, 3> corners;
    for (int c = 0; c < 3; ++c)  // the facet normal (12 bytes) is skipped: lucent computes its own
      for (int a = 0; a < 3; ++a) corners[c][a] = littleEndianFloat(facet + 12 + 12 * c + 4 * a);
    mesh.addTriangle(corners);
  }
}

/// The ASCII grammar, word by word: solid NAME {facet normal N N N outer loop {vertex X Y Z}x3
/// endloop endfacet}* endsolid NAME, and more solids after it.
class AsciiParser {
 public:
  AsciiParser(std::ifstream& in, const std::string& path) : mIn(in), mPath(path) {}

  void parse(WeldedMesh& mesh) {
    std::string word;
    while (mIn >> word) {
      if (word != "solid") expected("'solid'", word);
      skipLine();  // the solid's name
      while (next("'facet' or 'endsolid'") == "facet") readFacet(mesh);
      skipLine();
    }
  }

 private:
  void readFacet(WeldedMesh& mesh) {
    keyword("normal");
    for (int a = 0; a < 3; ++a) number();
    keyword("outer");
    keyword("loop");
    std::array<Corner, 3> corners;
    for (auto& corner : corners) {
      keyword("vertex");
      for (float& x : corner) x = float(number());
    }
    keyword("endloop");
    keyword("endfacet");
    mesh.addTriangle(corners);
  }

  std::string next(const std::string& what) {
    std::string word;
    if (!(mIn >> word))
      fail(mPath, "the file ends where " + what + " belongs (it is truncated)",
           "re-export or re-download the mesh");
    return word;
  }
  void keyword(const char* k) {
    const std::string word = next(std::string("'") + k + "'");
    if (word != k) expected(std::string("'") + k + "'", word);
  }
  double number() {
    const std::string word = next("a number");
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    if (end == word.c_str() || *end != '\0') expected("a number", word);
    return v;
  }
  [[noreturn]] void expected(const std::string& what, const std::string& word) {
    fail(mPath, what + " expected, not '" + word.substr(0, 40) + "'",
         "the file is not a valid ASCII STL; re-export it (binary STL is read too)");
  }
  void skipLine() {
    std::string rest;
    std::getline(mIn, rest);
  }

  std::ifstream& mIn;
  const std::string& mPath;
};
}  // namespace

vtkSmartPointer<vtkPolyData> readStl(const std::string& path) {
  const std::uint64_t bytes = std::filesystem::file_size(path);
  std::ifstream in(path, std::ios::binary);
  char head[kBinaryHeader] = {};
  in.read(head, sizeof head);
  const std::uint64_t read = std::uint64_t(in.gcount());
  in.clear();
  const std::uint64_t count =
      read == kBinaryHeader ? littleEndianU32(reinterpret_cast<unsigned char*>(head + 80)) : 0;
  const bool binary = read == kBinaryHeader && bytes == kBinaryHeader + kBinaryFacet * count;
  const bool ascii = !binary && std::strncmp(head, "solid", 5) == 0;
  WeldedMesh mesh(path);
  if (binary) {
    readBinary(in, count, mesh);
  } else if (ascii) {
    in.seekg(0);
    AsciiParser(in, path).parse(mesh);
  } else {
    fail(path,
         read < kBinaryHeader
             ? "the file is too short for an STL (" + std::to_string(bytes) + " bytes)"
             : "a binary STL declaring " + std::to_string(count) + " triangles needs " +
                   std::to_string(kBinaryHeader + kBinaryFacet * count) +
                   " bytes, but the file has " + std::to_string(bytes) +
                   " (it is truncated or corrupt)",
         "re-export or re-download the mesh");
  }
  if (mesh.triangles() == 0) fail(path, "the file holds no triangles", "is it the mesh you meant?");
  return mesh.polyData();
}

}  // namespace lucent::io
