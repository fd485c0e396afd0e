// The MetaImage header (ITK's MetaIO, https://itk.org/Wiki/ITK/MetaIO/Documentation) as VTK's
// vtkMetaImageReader reads it: "Key = Value" lines, ElementDataFile last, the values after it
// (LOCAL) or in a detached file. MetaIO allocates from NDims, DimSize, channels and
// CompressedDataSize as written (NDims 4 aborts, a huge CompressedDataSize throws bad_alloc):
// lucent checks them first.
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "../../util/error.hpp"
#include "volume_headers.hpp"

namespace lucent::io {

namespace {
constexpr const char* kMetaFix = "re-save it as a 3-D MetaImage (NDims = 3) or convert it to .vti";

/// Bytes per value of MetaIO's element types (an _ARRAY suffix names the same type); 0: other.
double metaTypeBytes(std::string type) {
  static const std::map<std::string, double> bytes = {
      {"MET_CHAR", 1},      {"MET_UCHAR", 1},      {"MET_SHORT", 2}, {"MET_USHORT", 2},
      {"MET_INT", 4},       {"MET_UINT", 4},       {"MET_LONG", 4},  {"MET_ULONG", 4},
      {"MET_LONG_LONG", 8}, {"MET_ULONG_LONG", 8}, {"MET_FLOAT", 4}, {"MET_DOUBLE", 8}};
  const std::string suffix = "_ARRAY";
  if (type.size() > suffix.size() &&
      type.compare(type.size() - suffix.size(), suffix.size(), suffix) == 0)
    type.resize(type.size() - suffix.size());
  const auto it = bytes.find(type);
  return it == bytes.end() ? 0 : it->second;
}

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

/// The numbers of `text` (NaN for a word that is not one).
std::vector<double> numbers(const std::string& text) {
  std::istringstream in(text);
  std::vector<double> out;
  for (std::string w; in >> w;) {
    double v = 0;
    out.push_back(parseNumber(w, v) ? v : NAN);
  }
  return out;
}

bool isTrue(const std::string& v) { return v == "True" || v == "true" || v == "1"; }

/// The header's keys and the byte after the ElementDataFile line.
struct MetaFields {
  std::map<std::string, std::string> keys;
  double dataOffset = 0;
};

MetaFields readMetaFields(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  MetaFields out;
  std::string line;
  constexpr int kMaxHeaderLines = 4096;  // real headers have about twenty
  for (int n = 0; std::getline(in, line); ++n) {
    const auto eq = line.find('=');
    if (n > kMaxHeaderLines || eq == std::string::npos)
      throw InputError(path + ": '" + trimmed(line).substr(0, 60) +
                       "' is not a MetaImage 'Key = Value' line before ElementDataFile; " +
                       kMetaFix);
    const std::string key = trimmed(line.substr(0, eq));
    out.keys[key] = trimmed(line.substr(eq + 1));
    if (key == "ElementDataFile") {
      out.dataOffset = double(in.tellg());
      return out;
    }
  }
  throw InputError(path + ": the header ends without ElementDataFile (where the values are); " +
                   kMetaFix);
}

std::string key(const MetaFields& f, const std::string& name, const std::string& otherwise) {
  const auto it = f.keys.find(name);
  return it == f.keys.end() ? otherwise : it->second;
}

void metaAxes(const std::string& path, const MetaFields& f, DeclaredVolume& d) {
  double nd = 0;
  if (!parseNumber(key(f, "NDims", ""), nd) || nd != 3)
    throw InputError(path + ": 'NDims = " + key(f, "NDims", "(missing)") +
                     "'; lucent reads 3-D volumes; " + kMetaFix);
  const auto dims = numbers(key(f, "DimSize", ""));
  if (dims.size() != 3)
    throw InputError(path + ": 'DimSize = " + key(f, "DimSize", "(missing)").substr(0, 60) +
                     "' does not give 3 sizes; " + kMetaFix);
  auto spacing = numbers(key(f, "ElementSpacing", key(f, "ElementSize", "1 1 1")));
  if (spacing.size() != 3)
    throw InputError(path + ": ElementSpacing does not give 3 numbers; " + kMetaFix);
  for (int a = 0; a < 3; ++a) d.dims[a] = dims[a], d.spacing[a] = spacing[a];
  if (!parseNumber(key(f, "ElementNumberOfChannels", "1"), d.components)) d.components = NAN;
  d.bytesPerValue = metaTypeBytes(key(f, "ElementType", ""));
  if (d.bytesPerValue == 0)
    throw InputError(path + ": 'ElementType = " + key(f, "ElementType", "(missing)") +
                     "' is not a number type VTK reads (MET_UCHAR ... MET_DOUBLE); " + kMetaFix);
}

void countMetaValues(const std::string& path, const MetaFields& f, DeclaredVolume& d) {
  const std::string file = key(f, "ElementDataFile", "");
  const bool local = file == "LOCAL" || file == "Local" || file == "local";
  if (!local && (file.find(' ') != std::string::npos || file == "LIST" ||
                 file.find('%') != std::string::npos))
    throw InputError(path + ": 'ElementDataFile = " + file.substr(0, 60) +
                     "' splits the values over several files; lucent reads one: " + kMetaFix);
  d.dataPath = local ? path : besideHeader(path, file);
  double headerSize = 0;
  if (!parseNumber(key(f, "HeaderSize", "0"), headerSize) || headerSize < -1)
    throw InputError(path + ": 'HeaderSize = " + key(f, "HeaderSize", "") +
                     "' is not -1 or a "
                     "byte count; " +
                     kMetaFix);
  const double dataBytes = fileBytes(d.dataPath), offset = local ? f.dataOffset : 0;
  const double available = dataBytes - offset - std::max(headerSize, 0.0);
  const double needed = valuesNeeded(d);
  if (isTrue(key(f, "CompressedData", "False"))) {
    double declared = 0;
    if (f.keys.count("CompressedDataSize") &&
        (!parseNumber(key(f, "CompressedDataSize", ""), declared) || declared > available))
      throw InputError(path + ": 'CompressedDataSize = " + key(f, "CompressedDataSize", "") +
                       "' but the file holds " + numberShown(available) +
                       " bytes of values; the file is truncated or its header wrong: " + kMetaFix);
    d.valuesPresent = std::floor(
        inflatedBytes(d.dataPath, offset + std::max(headerSize, 0.0), needed * d.bytesPerValue) /
        d.bytesPerValue);
  } else if (!isTrue(key(f, "BinaryData", "True"))) {
    d.valuesPresent = textTokens(d.dataPath, offset, needed);
  } else {
    d.valuesPresent =
        std::floor((headerSize == -1 ? dataBytes - offset : available) / d.bytesPerValue);
  }
}
}  // namespace

DeclaredVolume declaredMetaImage(const std::string& path) {
  const MetaFields fields = readMetaFields(path);
  DeclaredVolume d;
  d.dataPath = path;
  metaAxes(path, fields, d);
  checkDeclaredVolume(path, d);  // sizes and bounds before counting values
  countMetaValues(path, fields, d);
  checkDeclaredVolume(path, d);
  return d;
}

}  // namespace lucent::io
