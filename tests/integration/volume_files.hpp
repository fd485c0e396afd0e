#pragma once
// Volume files written byte by byte, sound or broken on purpose: NRRD, MetaImage, NIfTI-1 and
// DICOM slices, for the tests of lucent's header checks (test_volume_headers.cpp).
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace lucent::test {

/// A ball of radius 4 voxels whose values rise inwards (0 outside, 100 at 1 voxel in), `n`^3
/// voxels of 16-bit unsigned values.
inline std::vector<std::uint16_t> ballVoxels(int n) {
  std::vector<std::uint16_t> v;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = i - (n - 1) / 2.0, y = j - (n - 1) / 2.0, z = k - (n - 1) / 2.0;
        v.push_back(
            std::uint16_t(std::clamp(100 * (4 - std::sqrt(x * x + y * y + z * z)), 0.0, 300.0)));
      }
  return v;
}

inline std::string bytesOf(const std::vector<std::uint16_t>& v) {
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * 2);
}

/// gzip of `raw` (zlib's gzip wrapper, as NRRD's gzip encoding and .nii.gz use).
inline std::string gzipped(const std::string& raw) {
  z_stream z{};
  deflateInit2(&z, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY);
  std::string out(deflateBound(&z, uLong(raw.size())) + 32, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(raw.data()));
  z.avail_in = uInt(raw.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = uInt(out.size());
  deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

/// zlib (not gzip) of `raw`, as MetaImage's CompressedData holds it.
inline std::string zlibbed(const std::string& raw) {
  uLongf size = compressBound(uLong(raw.size()));
  std::string out(size, '\0');
  compress2(reinterpret_cast<Bytef*>(out.data()), &size, reinterpret_cast<const Bytef*>(raw.data()),
            uLong(raw.size()), 6);
  out.resize(size);
  return out;
}

inline void writeFile(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

/// A NIfTI-1 single-file header (348 bytes + 4 of extension flag) for `dims` 16-bit voxels.
inline std::string niftiHeader(int nx, int ny, int nz, short datatype = 512, short bitpix = 16,
                               short rank = 3, short nt = 1) {
  std::string h(352, '\0');
  const auto put = [&](std::size_t at, auto value) { std::memcpy(&h[at], &value, sizeof value); };
  put(0, std::int32_t(348));
  const short dim[8] = {rank, short(nx), short(ny), short(nz), nt, 1, 1, 1};
  for (int i = 0; i < 8; ++i) put(40 + 2 * i, dim[i]);
  put(70, datatype);
  put(72, bitpix);
  for (int i = 0; i < 8; ++i) put(76 + 4 * i, 1.0f);
  put(108, 352.0f);  // vox_offset
  put(112, 1.0f);    // scl_slope
  std::memcpy(&h[344], "n+1", 4);
  return h;
}

/// One explicit-VR little-endian element (PS3.5 7.1.2).
inline std::string dicomElement(std::uint16_t group, std::uint16_t elem, const char* vr,
                                const std::string& value) {
  std::string e(4, '\0');
  std::memcpy(&e[0], &group, 2), std::memcpy(&e[2], &elem, 2);
  e += vr;
  const bool longForm = std::string(vr) == "OW" || std::string(vr) == "OB";
  const std::uint32_t n = std::uint32_t(value.size());
  if (longForm)
    e += std::string(2, '\0') + std::string(reinterpret_cast<const char*>(&n), 4);
  else
    e += std::string(reinterpret_cast<const char*>(&n), 2);
  return e + value;
}

inline std::string us(std::uint16_t v) { return std::string(reinterpret_cast<const char*>(&v), 2); }

/// A DICOM slice (16-bit greyscale, explicit VR little endian) at z = `index`; `rows` is what its
/// Rows tag says, `pixels` its pixel data.
inline std::string dicomSlice(int index, std::uint16_t rows, std::uint16_t columns,
                              const std::string& pixels) {
  std::string s(128, '\0');
  s += "DICM";
  const std::string syntax = std::string("1.2.840.10008.1.2.1") + '\0';
  const std::string meta = dicomElement(0x0002, 0x0010, "UI", syntax);
  std::uint32_t metaLength = std::uint32_t(meta.size());
  s += dicomElement(0x0002, 0x0000, "UL",
                    std::string(reinterpret_cast<const char*>(&metaLength), 4));
  s += meta;
  std::string z = std::to_string(index);
  if (z.size() % 2) z += ' ';
  s += dicomElement(0x0008, 0x0016, "UI", std::string("1.2.840.10008.5.1.4.1.1.2") + '\0');
  s += dicomElement(0x0008, 0x0060, "CS", "CT");
  s += dicomElement(0x0018, 0x0050, "DS", "1 ");
  s += dicomElement(0x0020, 0x000D, "UI", "1.2.3.4.5.6");
  s += dicomElement(0x0020, 0x000E, "UI", "1.2.3.4.5.7");
  s += dicomElement(0x0020, 0x0013, "IS", z);
  s += dicomElement(0x0020, 0x0032, "DS", std::string("0\\0\\") + z + (z.size() % 2 ? "" : "  "));
  s += dicomElement(0x0020, 0x0037, "DS", "1\\0\\0\\0\\1\\0 ");
  s += dicomElement(0x0020, 0x1041, "DS", z);
  s += dicomElement(0x0028, 0x0002, "US", us(1));
  s += dicomElement(0x0028, 0x0004, "CS", "MONOCHROME2 ");
  s += dicomElement(0x0028, 0x0010, "US", us(rows));
  s += dicomElement(0x0028, 0x0011, "US", us(columns));
  s += dicomElement(0x0028, 0x0030, "DS", "1\\1 ");
  s += dicomElement(0x0028, 0x0100, "US", us(16));
  s += dicomElement(0x0028, 0x0101, "US", us(16));
  s += dicomElement(0x0028, 0x0102, "US", us(15));
  s += dicomElement(0x0028, 0x0103, "US", us(0));
  return s + dicomElement(0x7FE0, 0x0010, "OW", pixels);
}

/// The 2-D slice `k` of an `n`^3 ball as pixel bytes.
inline std::string ballSlice(int n, int k) {
  const auto v = ballVoxels(n);
  return bytesOf(std::vector<std::uint16_t>(v.begin() + k * n * n, v.begin() + (k + 1) * n * n));
}

}  // namespace lucent::test
