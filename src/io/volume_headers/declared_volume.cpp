#include "declared_volume.hpp"

#include <zlib.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <vector>

#include "../../util/error.hpp"
#include "../voxel_bound.hpp"

namespace lucent::io {

std::string numberShown(double v) {
  char b[40];
  std::snprintf(b, sizeof b, std::fabs(v) < 1e15 && v == std::floor(v) ? "%.0f" : "%.6g", v);
  return b;
}

namespace {
const auto shown = numberShown;

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
      throw InputError(path + ": the header declares " + shown(d.dims[a]) + " voxels along " +
                       kAxis[a] + "; sizes are whole numbers of at least 1: " + fix);
  checkVoxelCount(path + ": the header declares ", d.dims.data(), "reads",
                  "resample the volume (vtkImageResample, or ParaView's Resample To Image)");
  if (!wholeAtLeastOne(d.components) || d.components > kMaxVolumeComponents)
    throw InputError(path + ": the header declares " + shown(d.components) +
                     " values per voxel; lucent takes 1 to " + shown(kMaxVolumeComponents) +
                     " (a scalar, a vector or RGB(A)): extract one component or one volume");
  const double bytes = valuesNeeded(d) * d.bytesPerValue;
  if (!(bytes <= kMaxVolumeBytes))
    throw InputError(path + ": the header declares " + shown(bytes / 1e9) +
                     " GB of values, more than lucent reads (" + shown(kMaxVolumeBytes / 1e9) +
                     " GB); resample the volume or extract one component");
  for (int a = 0; a < 3; ++a)
    if (!(std::isfinite(d.spacing[a]) && d.spacing[a] > 0))
      throw InputError(path + ": the voxel spacing along " + kAxis[a] + " is " +
                       shown(d.spacing[a]) + "; spacing must be finite and positive: " + fix);
  if (d.valuesPresent >= 0 && d.valuesPresent < valuesNeeded(d))
    throw InputError(d.dataPath + ": holds " + shown(d.valuesPresent) + " of the " +
                     shown(valuesNeeded(d)) + " values the header of " + path +
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

double fileBytes(const std::string& path) {
  std::error_code ec;
  const auto n = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(path + ": cannot be read (" + ec.message() + "); give an existing file");
  return double(n);
}

namespace {
using GzFile = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

GzFile openAt(const std::string& path, double offset) {
  GzFile f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) throw InputError(path + ": cannot be opened; give a readable file");
  if (offset > 0 && std::fseek(f.get(), long(offset), SEEK_SET) != 0)
    throw InputError(path + ": cannot seek to its data; the file is truncated: re-export the scan");
  return f;
}

/// Streams the inflated bytes to `sink(bytes, n)` until the stream ends, `limit` bytes were
/// produced or `sink` returns false.
template <class Sink>
double inflateFrom(const std::string& path, double offset, double limit, Sink sink) {
  GzFile f = openAt(path, offset);
  z_stream z{};
  if (inflateInit2(&z, 15 + 32) != Z_OK)  // 15 + 32: zlib or gzip, by the stream's own header
    throw InputError(path + ": cannot start zlib");
  std::vector<unsigned char> in(1 << 16), out(1 << 16);
  double produced = 0;
  int rc = Z_OK;
  while (rc != Z_STREAM_END && produced < limit) {
    z.avail_in = unsigned(std::fread(in.data(), 1, in.size(), f.get()));
    if (z.avail_in == 0) break;  // the stream is cut short: fewer bytes than declared
    z.next_in = in.data();
    while (z.avail_in > 0 && rc != Z_STREAM_END && produced < limit) {
      z.avail_out = unsigned(out.size()), z.next_out = out.data();
      rc = inflate(&z, Z_NO_FLUSH);
      if (rc != Z_OK && rc != Z_STREAM_END && rc != Z_BUF_ERROR) {
        const std::string why = z.msg ? z.msg : "corrupt data";
        inflateEnd(&z);
        throw InputError(path + ": its compressed data is corrupt (zlib: " + why +
                         "); re-export the scan");
      }
      const std::size_t n = out.size() - z.avail_out;
      produced += double(n);
      if (!sink(out.data(), n)) return inflateEnd(&z), produced;
    }
  }
  inflateEnd(&z);
  return produced;
}
}  // namespace

double inflatedBytes(const std::string& path, double offset, double limit) {
  return inflateFrom(path, offset, limit, [](const unsigned char*, std::size_t) { return true; });
}

std::string inflatedPrefix(const std::string& path, std::size_t count) {
  std::string text;
  inflateFrom(path, 0, double(count), [&](const unsigned char* b, std::size_t n) {
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
