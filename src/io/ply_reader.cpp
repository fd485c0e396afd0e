#include "ply_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <vector>

#include <vtkCellArray.h>
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

std::string number(double v) {
  std::ostringstream o;
  o << std::setprecision(12) << v;
  return o.str();
}

enum class Format { Ascii, BinaryLittle, BinaryBig };

struct Property {
  std::string name;
  int size = 0;          ///< bytes of the scalar (or of a list's items)
  bool isFloat = false;  ///< float or double, else an integer type
  bool isSigned = true;
  bool list = false;
  int countSize = 0;  ///< bytes of a list's count
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

struct Header {
  Format format = Format::Ascii;
  std::vector<Element> elements;
  std::uint64_t bytes = 0;  ///< of the header, end_header line included
};

/// Size, float-ness and sign of a PLY scalar type name; false when unknown.
bool scalarType(const std::string& t, Property& p) {
  static const struct {
    const char* name;
    int size;
    bool isFloat, isSigned;
  } types[] = {
      {"char", 1, false, true},    {"int8", 1, false, true},    {"uchar", 1, false, false},
      {"uint8", 1, false, false},  {"short", 2, false, true},   {"int16", 2, false, true},
      {"ushort", 2, false, false}, {"uint16", 2, false, false}, {"int", 4, false, true},
      {"int32", 4, false, true},   {"uint", 4, false, false},   {"uint32", 4, false, false},
      {"float", 4, true, true},    {"float32", 4, true, true},  {"double", 8, true, true},
      {"float64", 8, true, true}};
  for (const auto& type : types)
    if (t == type.name) {
      p.size = type.size, p.isFloat = type.isFloat, p.isSigned = type.isSigned;
      return true;
    }
  return false;
}

Header readHeader(std::ifstream& in, const std::string& path) {
  std::string text;
  if (!std::getline(in, text) || text.rfind("ply", 0) != 0)
    fail(path, "it does not start with 'ply'", "is it a PLY file?");
  Header h;
  bool ended = false;
  while (!ended && std::getline(in, text)) {
    if (!text.empty() && text.back() == '\r') text.pop_back();
    std::istringstream words(text);
    std::string key;
    words >> key;
    if (key == "end_header") {
      ended = true;
    } else if (key == "format") {
      std::string f;
      words >> f;
      if (f == "ascii")
        h.format = Format::Ascii;
      else if (f == "binary_little_endian")
        h.format = Format::BinaryLittle;
      else if (f == "binary_big_endian")
        h.format = Format::BinaryBig;
      else
        fail(path, "unknown format '" + f + "'",
             "use ascii, binary_little_endian or binary_big_endian");
    } else if (key == "element") {
      Element e;
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
      // The bound holds for the whole file, however many element lines share the name.
      std::uint64_t total = e.count;
      for (const auto& other : h.elements)
        if (other.name == e.name) total += other.count;
      if (total > bound)
        fail(path,
             "the header declares more than " + std::to_string(bound) + " " + e.name +
                 " elements in all",
             "decimate the mesh first");
      h.elements.push_back(e);
    } else if (key == "property") {
      if (h.elements.empty())
        fail(path, "a property before any element", "the header is malformed");
      Property p;
      std::string type;
      words >> type;
      if (type == "list") {
        std::string countType, itemType;
        words >> countType >> itemType;
        Property count;
        if (!scalarType(countType, count) || count.isFloat || !scalarType(itemType, p))
          fail(path, "a list property of types '" + countType + " " + itemType + "'",
               "the header is malformed");
        p.list = true, p.countSize = count.size;
      } else if (!scalarType(type, p)) {
        fail(path, "a property of unknown type '" + type + "'", "the header is malformed");
      }
      words >> p.name;
      h.elements.back().properties.push_back(p);
    }
  }
  if (!ended)
    fail(path, "the header has no end_header line", "the file is truncated or not a PLY file");
  for (const auto& e : h.elements)  // it would be read e.count times from no bytes at all
    if (e.count > 0 && e.properties.empty())
      fail(path,
           "the element '" + e.name + "' has " + std::to_string(e.count) +
               " items but no properties",
           "the header is malformed");
  const auto at = in.tellg();
  h.bytes = at < 0 ? std::uint64_t(std::filesystem::file_size(path)) : std::uint64_t(at);
  return h;
}

/// The fewest bytes the elements can take: a list may be empty, an ASCII value is at least 2
/// characters.
void checkFits(const Header& h, const std::string& path) {
  std::uint64_t need = 0;
  for (const auto& e : h.elements) {
    std::uint64_t each = 0;
    for (const auto& p : e.properties)
      each += h.format == Format::Ascii ? 2 : std::uint64_t(p.list ? p.countSize : p.size);
    need += e.count * each;
  }
  const auto fileBytes = std::uint64_t(std::filesystem::file_size(path));
  if (fileBytes - h.bytes < need) {
    std::string declared;
    for (const auto& e : h.elements)
      declared += (declared.empty() ? "" : " and ") + std::to_string(e.count) + " " + e.name;
    fail(path,
         "its header declares " + declared + " elements, which take at least " +
             std::to_string(need) + " bytes, but only " + std::to_string(fileBytes - h.bytes) +
             " follow the header",
         "the file is truncated or its header is wrong; re-export it");
  }
}

/// Reads the values of one element, property by property.
class ValueReader {
 public:
  ValueReader(std::ifstream& in, Format format, const std::string& path)
      : mIn(in), mFormat(format), mPath(path) {}

  double scalar(const Property& p, int size) {
    if (mFormat == Format::Ascii) {
      std::string w;
      if (!(mIn >> w)) truncated();
      char* end = nullptr;
      const double v = std::strtod(w.c_str(), &end);
      if (*end != '\0')
        fail(mPath, "'" + w + "' where a number was expected", "the file is corrupt");
      return v;
    }
    unsigned char b[8];
    if (!mIn.read(reinterpret_cast<char*>(b), size)) truncated();
    if (mFormat == Format::BinaryBig) std::reverse(b, b + size);
    return decode(b, p, size);
  }

 private:
  static double decode(const unsigned char* b, const Property& p, int size) {
    if (p.isFloat) {
      if (size == 4) {
        float f;
        std::memcpy(&f, b, 4);
        return double(f);
      }
      double d;
      std::memcpy(&d, b, 8);
      return d;
    }
    std::uint64_t u = 0;
    for (int k = size - 1; k >= 0; --k) u = (u << 8) | b[k];
    if (p.isSigned && size < 8 && (u >> (8 * size - 1)) & 1)
      return double(std::int64_t(u) - (std::int64_t(1) << (8 * size)));
    return double(u);
  }
  [[noreturn]] void truncated() {
    fail(mPath, "the data ends before the elements its header declares", "re-export it");
  }

  std::ifstream& mIn;
  Format mFormat;
  const std::string& mPath;
};
}  // namespace

vtkSmartPointer<vtkPolyData> readPly(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const Header h = readHeader(in, path);
  checkFits(h, path);
  ValueReader read(in, h.format, path);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  std::uint64_t vertices = 0;
  for (const Element& e : h.elements) {
    const bool isVertex = e.name == "vertex", isFace = e.name == "face";
    for (std::uint64_t i = 0; i < e.count; ++i) {
      double xyz[3] = {0, 0, 0};
      for (const Property& p : e.properties) {
        if (!p.list) {
          const double v = read.scalar(p, p.size);
          const int axis = p.name == "x" ? 0 : p.name == "y" ? 1 : p.name == "z" ? 2 : -1;
          if (isVertex && axis >= 0) xyz[axis] = v;
          continue;
        }
        Property count = p;
        count.isFloat = false, count.isSigned = false;
        const double n = read.scalar(count, p.countSize);
        if (!(n >= 0 && n <= kMaxFaceCorners))
          fail(path, "a list of " + number(n) + " items", "the file is corrupt");
        std::vector<vtkIdType> ids;
        const bool indices = isFace && (p.name == "vertex_indices" || p.name == "vertex_index");
        for (int k = 0; k < int(n); ++k) {
          const double id = read.scalar(p, p.size);
          if (indices && !(id >= 0 && id < double(vertices) && id == std::floor(id)))
            fail(path,
                 "face " + std::to_string(i) + " names vertex " + number(id) + " of " +
                     std::to_string(vertices),
                 "vertex indices start at 0 and must name a vertex; re-export the mesh");
          if (indices) ids.push_back(vtkIdType(id));  // validated: in range, whole
        }
        if (isFace && (p.name == "vertex_indices" || p.name == "vertex_index") && ids.size() >= 3)
          polys->InsertNextCell(vtkIdType(ids.size()), ids.data());
      }
      if (isVertex) {
        if (!(std::abs(xyz[0]) <= kMaxCoordinate && std::abs(xyz[1]) <= kMaxCoordinate &&
              std::abs(xyz[2]) <= kMaxCoordinate))
          fail(path,
               "vertex " + std::to_string(i) +
                   " has a coordinate that is not a finite number of at most 1e30",
               "fix or remove that vertex");
        points->InsertNextPoint(xyz);
        ++vertices;
      }
    }
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(polys);
  return out;
}

}  // namespace lucent::io
