// The NRRD header (teem's format, http://teem.sourceforge.net/nrrd/format.html) as VTK's
// vtkNrrdReader reads it: "field: description" lines up to a blank line, the values after it or
// in one detached data file. VTK takes a fourth axis, or a first axis of 9 or fewer samples, for
// the values' components, and indexes the sizes without checking their count (dimension 0, 1 or 5
// crash it): lucent accepts what VTK reads right and names the rest.
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "../../util/error.hpp"
#include "volume_headers.hpp"

namespace lucent::io {

namespace {
constexpr const char* kNrrdFix = "re-save it as a 3-D scalar NRRD (unu), or convert it to .vti";

/// Bytes per value of NRRD's type names (all the spellings the format allows); 0: unknown.
double nrrdTypeBytes(const std::string& type) {
  static const std::map<std::string, double> bytes = {{"signed char", 1},
                                                      {"int8", 1},
                                                      {"int8_t", 1},
                                                      {"uchar", 1},
                                                      {"unsigned char", 1},
                                                      {"uint8", 1},
                                                      {"uint8_t", 1},
                                                      {"short", 2},
                                                      {"short int", 2},
                                                      {"signed short", 2},
                                                      {"signed short int", 2},
                                                      {"int16", 2},
                                                      {"int16_t", 2},
                                                      {"ushort", 2},
                                                      {"unsigned short", 2},
                                                      {"unsigned short int", 2},
                                                      {"uint16", 2},
                                                      {"uint16_t", 2},
                                                      {"int", 4},
                                                      {"signed int", 4},
                                                      {"int32", 4},
                                                      {"int32_t", 4},
                                                      {"uint", 4},
                                                      {"unsigned int", 4},
                                                      {"uint32", 4},
                                                      {"uint32_t", 4},
                                                      {"longlong", 8},
                                                      {"long long", 8},
                                                      {"long long int", 8},
                                                      {"signed long long", 8},
                                                      {"signed long long int", 8},
                                                      {"int64", 8},
                                                      {"int64_t", 8},
                                                      {"ulonglong", 8},
                                                      {"unsigned long long", 8},
                                                      {"unsigned long long int", 8},
                                                      {"uint64", 8},
                                                      {"uint64_t", 8},
                                                      {"float", 4},
                                                      {"double", 8}};
  const auto it = bytes.find(type);
  return it == bytes.end() ? 0 : it->second;
}

/// The header's fields, in order, and the byte where the values start (when attached).
struct NrrdFields {
  std::vector<std::pair<std::string, std::string>> fields;
  double dataOffset = -1;  ///< -1: no blank line (a detached header)
};

/// A header line just read, as VTK 9.1's parser can end it: VTK reads the header as a C string (it
/// stops at a NUL) of at most 4 MB and repeats its last line forever when that line has no newline.
void checkVtkCanEnd(std::istream& in, const std::string& line, const std::string& path) {
  constexpr double kVtkHeaderBytes = 0x400000 - 1;
  if (line.find('\0') != std::string::npos)
    throw InputError(path + ": the header line '" + printable(line) +
                     "' holds a NUL byte (VTK's reader would hang on it); " + kNrrdFix);
  if (in.eof())
    throw InputError(
        path + ": the header's last line '" + printable(line) +
        "' has no newline (VTK's reader would hang on it); end the header with a newline");
  if (double(in.tellg()) > kVtkHeaderBytes)
    throw InputError(path + ": the header is longer than VTK's 4 MB; " + kNrrdFix);
}

bool nrrdHeaderLine(std::istream& in, std::string& line, const std::string& path) {
  if (!headerLine(in, line, path)) return false;
  checkVtkCanEnd(in, line, path);
  return true;
}

NrrdFields readNrrdFields(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!headerLine(in, line, path) || line.compare(0, 4, "NRRD") != 0)
    throw InputError(path + ": not a NRRD file (its first line is not NRRD000X); " + kNrrdFix);
  checkVtkCanEnd(in, line, path);
  NrrdFields out;
  constexpr std::size_t kMaxLines = 4096, kMaxLine = 65536;  // real headers: tens of short lines
  while (nrrdHeaderLine(in, line, path)) {
    if (line.empty() || line == "\r") {  // the blank line VTK ends the header at
      out.dataOffset = double(in.tellg());
      return out;
    }
    if (out.fields.size() > kMaxLines || line.size() > kMaxLine)
      throw InputError(path + ": the header has more than 4096 lines or a line over 64 KB; " +
                       kNrrdFix);
    if (line[0] == '#') continue;
    const auto colon = line.find(": ");  // VTK looks for ": " first, then ":="
    if (colon == std::string::npos && line.find(":=") != std::string::npos) continue;
    if (colon == std::string::npos)
      throw InputError(path + ": the header line '" + printable(line) +
                       "' is not 'field: description'; " + kNrrdFix);
    out.fields.emplace_back(line.substr(0, colon), trimmed(line.substr(colon + 2)));
  }
  return out;
}

/// A whole decimal number as VTK's atoi reads it to the end (no 1e2, no 0x40); NaN otherwise.
double decimal(const std::string& text) {
  const std::size_t digits = text.size() - (text[0] == '-' ? 1 : 0);
  if (text.empty() || digits == 0 || digits > 15 ||
      text.find_first_not_of("0123456789", text.size() - digits) != std::string::npos)
    return NAN;  // "-" alone was a std::stod exception (found by fuzz_scan_nrrd)
  double value = 0;
  for (std::size_t i = text.size() - digits; i < text.size(); ++i)
    value = 10 * value + (text[i] - '0');
  return text[0] == '-' ? -value : value;
}

/// Spacings from "spacings" or the lengths of "space directions" vectors ("none": 0).
std::vector<double> nrrdSpacings(const std::string& field, const std::string& text) {
  std::vector<double> out;
  if (field == "spacings") {
    for (const std::string& w : words(text)) {
      double v = 0;
      out.push_back(parseNumber(w, v) ? v : (w == "nan" || w == "NaN" ? 0 : NAN));
    }
    return out;
  }
  for (const std::string& w : words(text)) {
    if (w == "none") {
      out.push_back(0);
      continue;
    }
    std::string inner = w;
    for (char& c : inner)
      if (c == '(' || c == ')' || c == ',') c = ' ';
    double sum = 0;
    for (const std::string& n : words(inner)) {
      double v = 0;
      sum += parseNumber(n, v) ? v * v : NAN;
    }
    out.push_back(std::sqrt(sum));
  }
  return out;
}
}  // namespace

namespace {
/// The fields lucent needs, each checked as it is read.
struct NrrdFacts {
  double dimension = 0;
  int dimensionLines = 0;
  std::vector<double> sizes, spacings;
  std::string encoding = "raw";
  bool spaceBeforeSizes = false;  ///< VTK then keeps only three sizes
};

/// The fields of the NRRD format (a key of one's own is written "key:=value"), as VTK knows them.
bool knownNrrdField(const std::string& field) {
  static const std::set<std::string> known = {"type",
                                              "dimension",
                                              "sizes",
                                              "spacings",
                                              "encoding",
                                              "data file",
                                              "datafile",
                                              "space",
                                              "labels",
                                              "space dimension",
                                              "space origin",
                                              "space directions",
                                              "endian",
                                              "line skip",
                                              "lineskip",
                                              "byte skip",
                                              "byteskip",
                                              "space units",
                                              "sample units",
                                              "sampleunits",
                                              "measurement frame",
                                              "block size",
                                              "blocksize",
                                              "content",
                                              "thicknesses",
                                              "axis mins",
                                              "axismins",
                                              "axis maxs",
                                              "axismaxs",
                                              "centers",
                                              "centerings",
                                              "units",
                                              "kinds",
                                              "min",
                                              "max",
                                              "old min",
                                              "oldmin",
                                              "old max",
                                              "oldmax",
                                              "number"};
  return known.count(field) > 0;
}

void readNrrdField(const std::string& path, const std::string& field, const std::string& text,
                   NrrdFacts& f, DeclaredVolume& d) {
  const std::string quoted = "'" + printable(field + ": " + text) + "'";
  if (!knownNrrdField(field))
    throw InputError(path + ": " + quoted +
                     " is not a NRRD field (a typo of 'spacings'? a key of "
                     "your own is written 'key:=value'); " +
                     kNrrdFix);
  if (field == "dimension" && (++f.dimensionLines > 1 || !f.sizes.empty()))
    throw InputError(path + ": " + quoted +
                     " is repeated or comes after 'sizes', and VTK's "
                     "reader then reads other sizes; give one dimension line first: " +
                     kNrrdFix);
  if (field == "dimension" && !std::isfinite(f.dimension = decimal(text)))
    throw InputError(path + ": " + quoted + " is not a whole decimal number; " + kNrrdFix);
  if (field == "space dimension" && decimal(text) != 3)
    throw InputError(path + ": " + quoted + "; lucent reads 3-D space: " + kNrrdFix);
  if (field == "sizes")
    for (const std::string& w : words(text))
      if (!std::isfinite(f.sizes.emplace_back(decimal(w))))
        throw InputError(path + ": " + quoted +
                         " are not whole decimal numbers (VTK reads them "
                         "with atoi); " +
                         kNrrdFix);
  if (field == "spacings" || field == "space directions") f.spacings = nrrdSpacings(field, text);
  if ((field == "space" || field == "space dimension") && f.sizes.empty())
    f.spaceBeforeSizes = true;
  if (field == "space" && text.find("time") != std::string::npos)
    throw InputError(path + ": " + quoted + " is a time series; " + kNrrdFix);
  if (field == "type" && (d.bytesPerValue = nrrdTypeBytes(text)) == 0)
    throw InputError(path + ": " + quoted + " is not a number type VTK reads; " + kNrrdFix);
  if (field == "encoding") {
    f.encoding = text;
    for (char& c : f.encoding) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (f.encoding == "gz") f.encoding = "gzip";
    if (f.encoding == "txt" || f.encoding == "text") f.encoding = "ascii";
    if (f.encoding == "ascii")  // VTK 9.1 parses the header as values and bytes as characters
      throw InputError(path + ": " + quoted +
                       " is misread by VTK's reader (it does not skip "
                       "the header); re-save it raw or gzip (unu save -e raw), or as .vti");
    if (f.encoding != "raw" && f.encoding != "gzip")
      throw InputError(path + ": " + quoted + " is not read by VTK (raw and gzip are); " +
                       kNrrdFix);
  }
  if (field == "data file" || field == "datafile") {
    const auto parts = words(text);
    if (parts.empty()) throw InputError(path + ": " + quoted + " names no file; " + kNrrdFix);
    if (parts.size() != 1 || parts[0] == "LIST")
      throw InputError(path + ": " + quoted +
                       " splits the values over several files; lucent "
                       "reads one data file: join them (unu join) or convert to .vti");
    d.dataPath = besideHeader(path, parts[0]);
  }
  if ((field == "byte skip" || field == "byteskip" || field == "line skip" ||
       field == "lineskip") &&
      text != "0")
    throw InputError(path + ": " + quoted + " is not read by VTK; " + kNrrdFix);
  if (field == "endian" && text != "little" && text != "big")
    throw InputError(path + ": " + quoted + " is neither little nor big; " + kNrrdFix);
}

/// Dims, components and spacing from the axes, as VTK's reader will take them.
void nrrdAxes(const std::string& path, const NrrdFacts& f, DeclaredVolume& d) {
  if (f.dimension != 3 && f.dimension != 4)
    throw InputError(path + ": 'dimension: " + numberShown(f.dimension) +
                     "'; lucent reads 3-D volumes (dimension 3, or 4 with the values' components "
                     "first); " +
                     kNrrdFix);
  if (double(f.sizes.size()) != f.dimension)
    throw InputError(path + ": 'sizes' gives " + std::to_string(f.sizes.size()) +
                     " numbers for dimension " + numberShown(f.dimension) + "; " + kNrrdFix);
  if (f.dimension == 4 && f.spaceBeforeSizes)
    throw InputError(path +
                     ": 'space' comes before 'sizes' in a 4-D header, and VTK's reader "
                     "then drops the fourth size; put 'sizes' first, or convert to .vti");
  const std::size_t first = f.dimension == 4 ? 1 : 0;
  if (!f.spacings.empty() && f.spacings.size() != f.sizes.size())
    throw InputError(path + ": " + std::to_string(f.spacings.size()) + " spacings for " +
                     std::to_string(f.sizes.size()) +
                     " axes (VTK's reader would shift them; give "
                     "'none' for the components' axis); " +
                     kNrrdFix);
  d.components = first ? f.sizes[0] : 1;
  for (int a = 0; a < 3; ++a) {
    d.dims[a] = f.sizes[first + a];
    if (!f.spacings.empty()) d.spacing[a] = f.spacings[first + a];
  }
}

/// How many values the data holds (counted up to the number needed).
void countNrrdValues(const std::string& path, const NrrdFacts& f, double dataOffset,
                     DeclaredVolume& d) {
  const bool attached = d.dataPath == path;
  if (attached && dataOffset < 0)
    throw InputError(path +
                     ": the header neither ends in a blank line before the values nor "
                     "names a 'data file'; " +
                     kNrrdFix);
  const double offset = attached ? dataOffset : 0, bytes = fileBytes(d.dataPath) - offset;
  if (f.encoding == "raw") return void(d.valuesPresent = valuesIn(bytes, d.bytesPerValue));
  // VTK's gzip path reads one value per voxel (not per component) through gzread, whose count is
  // an int: both would leave most of the volume uninitialised.
  const double needed = valuesNeeded(d) * d.bytesPerValue;
  if (d.components != 1 || needed >= 2147483647.0)
    throw InputError(path + ": gzip NRRD with " + numberShown(d.components) + " components and " +
                     numberShown(needed) +
                     " bytes: VTK's reader takes one component under 2 GB "
                     "compressed; re-save it raw (unu save -e raw), or as .vti");
  d.valuesPresent = valuesIn(inflatedBytes(d.dataPath, offset, needed, Compression::Gzip, bytes),
                             d.bytesPerValue);
}
}  // namespace

std::string nrrdDataFile(const std::string& path) {
  for (const auto& [field, text] : readNrrdFields(path).fields)
    if ((field == "data file" || field == "datafile") && words(text).size() == 1)
      return besideHeader(path, words(text)[0]);
  return "";
}

DeclaredVolume declaredNrrd(const std::string& path) {
  const NrrdFields header = readNrrdFields(path);
  DeclaredVolume d;
  d.dataPath = path;
  NrrdFacts facts;
  for (const auto& [field, text] : header.fields) readNrrdField(path, field, text, facts, d);
  if (d.bytesPerValue == 0) throw InputError(path + ": the header has no 'type'; " + kNrrdFix);
  nrrdAxes(path, facts, d);
  checkDeclaredVolume(path, d);  // sizes and bounds before counting values
  if (facts.dimension == 3 && d.dims[0] <= 9)
    throw InputError(path + ": the first axis has " + numberShown(d.dims[0]) +
                     " samples, and VTK's reader takes 9 or fewer for the components of a 2-D "
                     "image; give it at least 10 samples, or convert to .vti");
  countNrrdValues(path, facts, header.dataOffset, d);
  checkDeclaredVolume(path, d);
  return d;
}

}  // namespace lucent::io
