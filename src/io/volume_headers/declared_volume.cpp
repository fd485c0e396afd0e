#include "declared_volume.hpp"

#include <zlib.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <vector>

#include "../../util/error.hpp"
#include "../voxel_bound.hpp"

#include <lucent/scene/voxel_grid.hpp>

namespace lucent::io {

namespace {

bool wholeAtLeastOne(double v) { return std::isfinite(v) && v >= 1 && v == std::floor(v); }

constexpr const char* kAxis[3] = {"x", "y", "z"};
}  // namespace

double valuesNeeded(const DeclaredVolume& d) {
  return d.dims[0] * d.dims[1] * d.dims[2] * d.components;
}

void checkDeclaredVolume(const std::string& path, const DeclaredVolume& d) {
  const std::string fix = kReexportFix;
  for (int a = 0; a < 3; ++a)
    if (!wholeAtLeastOne(d.dims[a]))
      throw InputError(path + ": the header declares " + numberShown(d.dims[a]) + " voxels along " +
                       kAxis[a] + "; sizes are whole numbers of at least 1: " + fix);
  checkVoxelCount(path + ": the header declares ", d.dims.data(), "reads",
                  "resample the volume (vtkImageResample, or ParaView's Resample To Image)");
  if (!wholeAtLeastOne(d.components) || d.components > kMaxVolumeComponents)
    throw InputError(path + ": the header declares " + numberShown(d.components) +
                     " values per voxel; lucent takes 1 to " + numberShown(kMaxVolumeComponents) +
                     " (a scalar, a vector or RGB(A)): extract one component or one volume");
  const double bytes = valuesNeeded(d) * d.bytesPerValue;
  if (!(bytes <= kMaxVolumeBytes))
    throw InputError(path + ": the header declares " + numberShown(bytes / 1e9) +
                     " GB of values, more than lucent reads (" +
                     numberShown(kMaxVolumeBytes / 1e9) +
                     " GB); resample the volume or extract one component");
  const std::string spacing = scene::spacingProblem(d.spacing.data());
  if (!spacing.empty()) throw InputError(path + ": " + spacing + ": " + fix);
  if (d.valuesPresent != kUnknown && d.valuesPresent < valuesNeeded(d))
    throw InputError(d.dataPath + ": holds " + numberShown(d.valuesPresent) + " of the " +
                     numberShown(valuesNeeded(d)) + " values the header of " + path +
                     " declares; the file is truncated or its header wrong: re-export the scan");
}

bool parseNumber(const std::string& text, double& value) {
  const char* begin = text.c_str();
  while (std::isspace(static_cast<unsigned char>(*begin))) ++begin;
  if (!*begin) return false;
  char* end = nullptr;
  value = std::strtod(begin, &end);
  while (std::isspace(static_cast<unsigned char>(*end))) ++end;
  return *end == '\0' && std::isfinite(value);
}

bool headerLine(std::istream& in, std::string& line, const std::string& path,
                std::size_t maxBytes) {
  line.clear();
  for (int c; (c = in.get()) != EOF;) {
    if (c == '\n') return true;
    if (line.size() == maxBytes)
      throw InputError(path + ": a header line is longer than " + numberShown(double(maxBytes)) +
                       " bytes: not a volume header; " + kReexportFix);
    line += char(c);
  }
  return !line.empty();
}

std::string printable(const std::string& text, std::size_t max) {
  std::string out = text.substr(0, max);
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
  return out;
}

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string> words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

double fileBytes(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))  // not a device or FIFO: reads must end
    throw InputError(
        path + ": " +
        (std::filesystem::exists(path, ec) ? "is not a regular file" : "no such file") +
        "; give the volume's data as a file");
  const auto n = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(path + ": cannot be read (" + ec.message() + "); give a readable file");
  return double(n);
}

double valuesIn(double bytes, double bytesPerValue) {
  return std::floor(std::max(0.0, bytes) / bytesPerValue);
}

namespace {
using GzFile = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

GzFile openAt(const std::string& path, double offset) {
  if (!(offset >= 0 && offset <= fileBytes(path)))  // also keeps long(offset) defined
    throw InputError(
        path + ": its data would start at byte " + numberShown(offset) +
        ", past the end of the file; the file is truncated or its header wrong: " + kReexportFix);
  GzFile f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) throw InputError(path + ": cannot be opened; give a readable file");
  if (offset > 0 && std::fseek(f.get(), long(offset), SEEK_SET) != 0)
    throw InputError(path + ": cannot seek to its data; the file is truncated: re-export the scan");
  return f;
}

[[noreturn]] void corrupt(const std::string& path, const z_stream& z) {
  throw InputError(path + ": its compressed data is corrupt (zlib: " +
                   (z.msg ? z.msg : "not a " + std::string("stream of this kind")) +
                   "); re-export the scan");
}

/// Streams the inflated bytes to `sink(bytes, n)` until the data ends (gzip: every member, as
/// gzread reads them), `limit` bytes were produced, `inputLimit` compressed bytes were read, or
/// `sink` returns false.
template <class Sink>
double inflateFrom(const std::string& path, double offset, double limit, Compression kind,
                   double inputLimit, Sink sink) {
  GzFile f = openAt(path, offset);
  z_stream z{};
  if (inflateInit2(&z, kind == Compression::Gzip ? 15 + 16 : 15) != Z_OK)
    throw InputError(path + ": zlib could not start (out of memory?); try again");
  std::vector<unsigned char> in(1 << 16), out(1 << 16);
  double produced = 0, consumed = 0;
  int rc = Z_OK;
  while (produced < limit && consumed < inputLimit) {
    const auto want = std::size_t(std::min(double(in.size()), inputLimit - consumed));
    z.avail_in = unsigned(std::fread(in.data(), 1, want, f.get()));
    if (z.avail_in == 0) break;  // the data is cut short: fewer bytes than declared
    consumed += z.avail_in;
    z.next_in = in.data();
    while (z.avail_in > 0 && produced < limit) {
      if (rc == Z_STREAM_END) {  // another gzip member follows (bgzip, concatenated files)
        if (kind != Compression::Gzip) break;
        inflateReset(&z);
      }
      z.avail_out = unsigned(out.size()), z.next_out = out.data();
      rc = inflate(&z, Z_NO_FLUSH);
      if (rc != Z_OK && rc != Z_STREAM_END && rc != Z_BUF_ERROR) {
        const z_stream copy = z;
        inflateEnd(&z);
        corrupt(path, copy);
      }
      const std::size_t n = out.size() - z.avail_out;
      produced += double(n);
      if (!sink(out.data(), n)) return inflateEnd(&z), produced;
    }
    if (rc == Z_STREAM_END && kind != Compression::Gzip) break;
  }
  inflateEnd(&z);
  return produced;
}
}  // namespace

double inflatedBytes(const std::string& path, double offset, double limit, Compression kind,
                     double inputLimit) {
  return inflateFrom(path, offset, limit, kind, inputLimit,
                     [](const unsigned char*, std::size_t) { return true; });
}

std::string inflatedPrefix(const std::string& path, std::size_t count) {
  std::string text;
  inflateFrom(path, 0, double(count), Compression::Gzip, fileBytes(path),
              [&](const unsigned char* b, std::size_t n) {
                text.append(reinterpret_cast<const char*>(b), std::min(n, count - text.size()));
                return text.size() < count;
              });
  return text;
}

double textTokens(const std::string& path, double offset, double limit) {
  GzFile f = openAt(path, offset);
  double tokens = 0;
  bool inToken = false;
  for (int c; tokens < limit && (c = std::fgetc(f.get())) != EOF;) {
    const bool space = std::isspace(c) != 0;
    if (!space && !inToken) ++tokens;
    inToken = !space;
  }
  return tokens;
}

std::string besideHeader(const std::string& headerPath, const std::string& name) {
  const std::filesystem::path p(name);
  if (p.is_absolute()) return name;
  return (std::filesystem::path(headerPath).parent_path() / p).string();
}

}  // namespace lucent::io
