// The legacy VTK format's STRUCTURED_POINTS header (VTK User's Guide, "VTK File Formats"): a
// version line, a title, ASCII or BINARY, then keyword lines up to the first point-data array.
// Checked like every other volume header: sizes, spacing, and the values the array needs.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "../../util/error.hpp"
#include "volume_headers.hpp"

namespace lucent::io {

namespace {
constexpr const char* kVtkFix = "re-save it as image data (.vti) from ParaView";

/// Bytes per value of the legacy format's type names whose size is fixed; 0: other.
double legacyTypeBytes(std::string type) {
  static const std::map<std::string, double> bytes = {
      {"unsigned_char", 1}, {"char", 1},         {"signed_char", 1},  {"unsigned_short", 2},
      {"short", 2},         {"unsigned_int", 4}, {"int", 4},          {"float", 4},
      {"double", 8},        {"vtktypeint64", 8}, {"vtktypeuint64", 8}};
  std::transform(type.begin(), type.end(), type.begin(), ::tolower);
  const auto it = bytes.find(type);
  return it == bytes.end() ? 0 : it->second;
}

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), ::toupper);
  return s;
}

/// Three numbers after a keyword, or NaNs.
void three(const std::vector<std::string>& w, std::array<double, 3>& out) {
  for (int a = 0; a < 3; ++a)
    if (w.size() < 4 || !parseNumber(w[1 + a], out[a])) out[a] = NAN;
}
}  // namespace

DeclaredVolume declaredLegacyVtk(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string version, title, encoding, line;
  headerLine(in, version, path), headerLine(in, title, path), headerLine(in, encoding, path);
  if (version.compare(0, 5, "# vtk") != 0)
    throw InputError(path + ": not a legacy VTK file (no '# vtk DataFile' first line); " + kVtkFix);
  const bool binary = upper(words(encoding).empty() ? "" : words(encoding)[0]) == "BINARY";
  DeclaredVolume d;
  d.dataPath = path;
  double points = -1;
  for (int n = 0; headerLine(in, line, path) && n < 256; ++n) {
    const auto w = words(line);
    if (w.empty()) continue;
    const std::string key = upper(w[0]);
    if (key == "DATASET" && (w.size() < 2 || upper(w[1]) != "STRUCTURED_POINTS"))
      throw InputError(path + ": the dataset is " + (w.size() < 2 ? "unnamed" : printable(w[1])) +
                       ", not STRUCTURED_POINTS (a volume); " + kVtkFix);
    if (key == "DIMENSIONS") three(w, d.dims);
    if (key == "SPACING" || key == "ASPECT_RATIO") three(w, d.spacing);
    if (key == "POINT_DATA" && (w.size() < 2 || !parseNumber(w[1], points))) points = NAN;
    if (key == "CELL_DATA" && points == -1) {  // cell arrays first (vtkStructuredPointsWriter's
      d.valuesPresent = kUnknown;              // order): their values are not lines to read
      d.components = 1, d.bytesPerValue = 8;
      checkDeclaredVolume(path, d);
      return d;
    }
    if ((key != "SCALARS" && key != "VECTORS") || points == -1) continue;
    d.components = key == "VECTORS" ? 3 : 1;
    if (key == "SCALARS" && w.size() > 3 && !parseNumber(w[3], d.components)) d.components = NAN;
    d.bytesPerValue = w.size() > 2 ? legacyTypeBytes(w[2]) : 0;
    if (key == "SCALARS" && !headerLine(in, line, path)) break;  // its LOOKUP_TABLE line
    const bool sized = d.bytesPerValue > 0;
    if (!sized) d.bytesPerValue = 8;  // bit, long, vtkIdType: bound as 8 bytes, not counted
    checkDeclaredVolume(path, d);
    if (!(points == d.dims[0] * d.dims[1] * d.dims[2]))
      throw InputError(path + ": POINT_DATA " + numberShown(points) +
                       " disagrees with DIMENSIONS " + numberShown(d.dims[0]) + " " +
                       numberShown(d.dims[1]) + " " + numberShown(d.dims[2]) + "; " + kVtkFix);
    const double offset = double(in.tellg());
    if (sized)
      d.valuesPresent = binary ? std::floor((fileBytes(path) - offset) / d.bytesPerValue)
                               : textTokens(path, offset, valuesNeeded(d));
    checkDeclaredVolume(path, d);
    return d;
  }
  throw InputError(path + ": no SCALARS or VECTORS point data within the header; " + kVtkFix);
}

}  // namespace lucent::io
