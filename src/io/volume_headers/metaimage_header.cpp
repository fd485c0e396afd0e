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

/// Bytes per value of the element types VTK 9.1's MetaImage reader maps to a VTK type of the same
/// size (MET_LONG is 4 bytes in MetaIO but VTK_LONG 8; 64-bit and float arrays VTK refuses after
/// sizing the output to one voxel); 0: other.
double metaTypeBytes(const std::string& type) {
  static const std::map<std::string, double> bytes = {
      {"MET_CHAR", 1},        {"MET_UCHAR", 1},       {"MET_SHORT", 2},
      {"MET_USHORT", 2},      {"MET_INT", 4},         {"MET_UINT", 4},
      {"MET_FLOAT", 4},       {"MET_DOUBLE", 8},      {"MET_CHAR_ARRAY", 1},
      {"MET_UCHAR_ARRAY", 1}, {"MET_SHORT_ARRAY", 2}, {"MET_USHORT_ARRAY", 2},
      {"MET_INT_ARRAY", 4},   {"MET_UINT_ARRAY", 4}};
  const auto it = bytes.find(type);
  return it == bytes.end() ? 0 : it->second;
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

/// As MetaIO reads a boolean: by its first character.
bool isTrue(const std::string& v) {
  return !v.empty() && (v[0] == 'T' || v[0] == 't' || v[0] == '1');
}

/// The header's keys and the byte after the ElementDataFile line.
struct MetaFields {
  std::map<std::string, std::string> keys;
  double dataOffset = 0;
};

MetaFields readMetaFields(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  MetaFields out;
  std::string line;
  constexpr int kMaxHeaderLines = 4096;   // real headers have about twenty short lines
  constexpr std::size_t kMaxLine = 1024;  // VTK's CanReadFile reads the first key into 8000 bytes
  for (int n = 0; headerLine(in, line, path); ++n) {
    if (trimmed(line).empty() && n < kMaxHeaderLines) continue;
    auto sep = line.find('=');
    if (sep == std::string::npos) sep = line.find(':');
    const std::string key = sep == std::string::npos ? "" : trimmed(line.substr(0, sep));
    if (n > kMaxHeaderLines || line.size() > kMaxLine || key.empty() ||
        key.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_") !=
            std::string::npos)
      throw InputError(path + ": '" + printable(trimmed(line)) +
                       "' is not a MetaImage 'Key = Value' line before ElementDataFile; " +
                       kMetaFix);
    if (!out.keys.emplace(key, trimmed(line.substr(sep + 1))).second)
      throw InputError(path + ": the key " + key +
                       " is given twice (MetaIO would apply both, in "
                       "order); " +
                       kMetaFix);
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
    throw InputError(path + ": 'NDims = " + printable(key(f, "NDims", "(missing)")) +
                     "'; lucent reads 3-D volumes; " + kMetaFix);
  const auto dims = numbers(key(f, "DimSize", ""));
  if (dims.size() != 3)
    throw InputError(path + ": 'DimSize = " + printable(key(f, "DimSize", "(missing)")) +
                     "' does not give 3 sizes; " + kMetaFix);
  auto spacing = numbers(key(f, "ElementSpacing", key(f, "ElementSize", "1 1 1")));
  if (spacing.size() != 3)
    throw InputError(path + ": ElementSpacing does not give 3 numbers; " + kMetaFix);
  for (int a = 0; a < 3; ++a) {
    d.dims[a] = dims[a], d.spacing[a] = std::fabs(spacing[a]);  // VTK's MetaIO reads the magnitude
    if (spacing[a] < 0)
      d.notes.push_back(path + ": ElementSpacing along " + "xyz"[a] + " is " +
                        numberShown(spacing[a]) + ": read as " + numberShown(-spacing[a]) +
                        " mm, as VTK does");
  }
  if (!parseNumber(key(f, "ElementNumberOfChannels", "1"), d.components)) d.components = NAN;
  d.bytesPerValue = metaTypeBytes(key(f, "ElementType", ""));
  if (d.bytesPerValue == 0)
    throw InputError(path + ": 'ElementType = " + printable(key(f, "ElementType", "(missing)")) +
                     "' is not a number type VTK reads (MET_UCHAR ... MET_DOUBLE); " + kMetaFix);
}

/// The compressed bytes MetaIO will inflate: CompressedDataSize (needed for LOCAL data, where
/// MetaIO otherwise inflates the header), bounded by what the file holds.
double compressedBytes(const std::string& path, const MetaFields& f, bool local, double available) {
  double declared = available;
  const bool given = f.keys.count("CompressedDataSize") > 0;
  if (given && !(parseNumber(key(f, "CompressedDataSize", ""), declared) && declared >= 1 &&
                 declared == std::floor(declared) && declared <= available))
    throw InputError(path +
                     ": 'CompressedDataSize = " + printable(key(f, "CompressedDataSize", "")) +
                     "' but the file holds " + numberShown(std::max(0.0, available)) +
                     " bytes of values; the file is truncated or its header wrong: " + kMetaFix);
  if (!given && local)
    throw InputError(path +
                     ": compressed LOCAL data needs CompressedDataSize (MetaIO would "
                     "inflate the header); " +
                     kMetaFix);
  if (declared > kMaxVolumeBytes)
    throw InputError(path + ": " + numberShown(declared) +
                     " compressed bytes, more than lucent "
                     "reads; resample the volume");
  return declared;
}

void countMetaValues(const std::string& path, const MetaFields& f, DeclaredVolume& d) {
  const std::string file = key(f, "ElementDataFile", "");
  const bool local = file == "LOCAL" || file == "Local" || file == "local";
  if (!local && (file == "LIST" || file.find('%') != std::string::npos))
    throw InputError(path + ": 'ElementDataFile = " + printable(file) +
                     "' splits the values over several files; lucent reads one: " + kMetaFix);
  d.dataPath = local ? path : besideHeader(path, file);
  double headerSize = 0;
  const double dataBytes = fileBytes(d.dataPath);
  if (!parseNumber(key(f, "HeaderSize", "0"), headerSize) || headerSize < -1 ||
      headerSize > dataBytes || headerSize != std::floor(headerSize))
    throw InputError(path + ": 'HeaderSize = " + printable(key(f, "HeaderSize", "")) +
                     "' is not -1 or a byte count within the data file; " + kMetaFix);
  // MetaIO seeks to HeaderSize from the data file's start; 0 means right after a LOCAL header.
  const double start = headerSize > 0 ? headerSize : (local ? f.dataOffset : 0);
  const double needed = valuesNeeded(d);
  const bool compressed = isTrue(key(f, "CompressedData", "False"));
  if (compressed && headerSize == -1)
    throw InputError(path + ": 'HeaderSize = -1' with compressed data (MetaIO cannot find it); " +
                     kMetaFix);
  if (compressed)
    d.valuesPresent =
        valuesIn(inflatedBytes(d.dataPath, start, needed * d.bytesPerValue, Compression::Zlib,
                               compressedBytes(path, f, local, dataBytes - start)),
                 d.bytesPerValue);
  else if (!isTrue(key(f, "BinaryData", "True")))
    d.valuesPresent = textTokens(d.dataPath, start, needed);
  else  // HeaderSize -1: the values are the file's last bytes
    d.valuesPresent =
        valuesIn(headerSize == -1 ? dataBytes - (local ? f.dataOffset : 0) : dataBytes - start,
                 d.bytesPerValue);
}
}  // namespace

std::string metaImageDataFile(const std::string& path) {
  const std::string file = key(readMetaFields(path), "ElementDataFile", "LOCAL");
  if (file == "LOCAL" || file == "Local" || file == "local" || file == "LIST") return "";
  return besideHeader(path, file);
}

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
