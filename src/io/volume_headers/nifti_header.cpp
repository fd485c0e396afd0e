// The NIfTI header (https://nifti.nimh.nih.gov/nifti-1, NIfTI-2:
// https://nifti.nimh.nih.gov/nifti-2): a fixed binary record at the start of the file (gzipped as a
// whole in .nii.gz), in either byte order, read here field by field at the offsets the standard
// gives. VTK's reader allocates from dim[] and datatype as written (an unknown datatype asked
// for 5.6 GB).
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>

#include "../../util/error.hpp"
#include "volume_headers.hpp"

namespace lucent::io {

namespace {
constexpr const char* kNiftiFix = "re-save it as a 3-D NIfTI (e.g. fslmaths, nibabel) or as .vti";

/// A header's bytes read in its own byte order.
struct HeaderBytes {
  std::string bytes;
  bool swapped = false;

  template <class T>
  T at(std::size_t offset) const {
    unsigned char b[sizeof(T)];
    std::memcpy(b, bytes.data() + offset, sizeof(T));
    if (swapped)
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    T v;
    std::memcpy(&v, b, sizeof(T));
    return v;
  }
};

/// Bytes per value and values per voxel of a NIfTI datatype code; false for codes VTK cannot
/// turn into real values (complex, bit, 128-bit float) or that are not codes at all.
bool niftiType(int code, double& bytes, double& components) {
  components = 1;
  switch (code) {
    case 2:
    case 256:
      bytes = 1;
      return true;  // uint8, int8
    case 4:
    case 512:
      bytes = 2;
      return true;  // int16, uint16
    case 8:
    case 768:
    case 16:
      bytes = 4;
      return true;  // int32, uint32, float32
    case 64:
    case 1024:
    case 1280:
      bytes = 8;
      return true;  // float64, int64, uint64
    case 128:
      bytes = 1, components = 3;
      return true;  // RGB24
    case 2304:
      bytes = 1, components = 4;
      return true;  // RGBA32
    default:
      return false;
  }
}

/// Reads the header record; NIfTI-1 is 348 bytes, NIfTI-2 540.
HeaderBytes niftiHeader(const std::string& path, bool gz) {
  HeaderBytes h;
  if (gz) {
    h.bytes = inflatedPrefix(path, 540);
  } else {
    std::ifstream in(path, std::ios::binary);
    h.bytes.resize(540);
    in.read(h.bytes.data(), 540);
    h.bytes.resize(std::size_t(in.gcount()));
  }
  if (h.bytes.size() < 348)
    throw InputError(path + ": " + std::to_string(h.bytes.size()) +
                     " bytes, shorter than a NIfTI header (348); the file is truncated or not "
                     "NIfTI: " +
                     kNiftiFix);
  const auto size = h.at<std::int32_t>(0);
  h.swapped = size != 348 && size != 540;
  const auto swappedSize = h.at<std::int32_t>(0);
  if (h.swapped && swappedSize != 348 && swappedSize != 540)
    throw InputError(path + ": not a NIfTI file (its header size field is neither 348 nor 540); " +
                     kNiftiFix);
  if (h.at<std::int32_t>(0) == 540 && h.bytes.size() < 540)
    throw InputError(path + ": shorter than a NIfTI-2 header (540 bytes); " + kNiftiFix);
  return h;
}
}  // namespace

namespace {
/// The NIfTI-1 or -2 fields lucent needs, in doubles.
struct NiftiFields {
  double dim[8], pixdim[8], voxOffset, sclSlope, sclInter;
  int datatype, bitpix;
};

NiftiFields niftiFields(const std::string& path, const HeaderBytes& h) {
  NiftiFields f{};
  const bool two = h.at<std::int32_t>(0) == 540;
  const char* magic = h.bytes.data() + (two ? 4 : 344);
  if (std::strncmp(magic, two ? "n+2" : "n+1", 4) != 0)
    throw InputError(path +
                     (std::strncmp(magic, "ni1", 4) == 0 || std::strncmp(magic, "ni2", 4) == 0
                          ? ": a NIfTI header whose values are in a separate .img file; "
                            "give a single-file .nii: "
                          : ": the NIfTI magic is missing; ") +
                     kNiftiFix);
  for (int i = 0; i < 8; ++i) {
    f.dim[i] = two ? double(h.at<std::int64_t>(16 + 8 * i)) : h.at<std::int16_t>(40 + 2 * i);
    f.pixdim[i] = two ? h.at<double>(104 + 8 * i) : h.at<float>(76 + 4 * i);
  }
  f.datatype = h.at<std::int16_t>(two ? 12 : 70);
  f.bitpix = h.at<std::int16_t>(two ? 14 : 72);
  f.voxOffset = two ? double(h.at<std::int64_t>(168)) : h.at<float>(108);
  f.sclSlope = two ? h.at<double>(176) : h.at<float>(112);
  f.sclInter = two ? h.at<double>(184) : h.at<float>(116);
  if (!std::isfinite(f.sclSlope) || (f.sclSlope != 0 && !std::isfinite(f.sclInter)))
    throw InputError(path + ": the rescale (scl_slope " + numberShown(f.sclSlope) + ", scl_inter " +
                     numberShown(f.sclInter) + ") is not finite; " + kNiftiFix);
  return f;
}

void niftiAxes(const std::string& path, const NiftiFields& f, DeclaredVolume& d) {
  const double rank = f.dim[0];
  if (!(rank >= 3 && rank <= 7))
    throw InputError(path + ": dim[0] is " + numberShown(rank) +
                     "; a NIfTI volume has 3 to 7 dimensions (the first 3 spatial): " + kNiftiFix);
  double volumes = 1;
  for (int i = 4; i <= int(rank); ++i) {
    if (!(f.dim[i] >= 1))
      throw InputError(path + ": dim[" + std::to_string(i) + "] is " + numberShown(f.dim[i]) +
                       "; every size is at least 1: " + kNiftiFix);
    volumes *= f.dim[i];
  }
  if (volumes != 1)
    throw InputError(path + ": holds " + numberShown(volumes) +
                     " volumes (dim[4..7]: a time "
                     "series or vectors); lucent reads one: extract it (e.g. fslroi in out 0 1)");
  for (int a = 0; a < 3; ++a) {
    d.dims[a] = f.dim[1 + a];
    // Real files carry pixdim 0 (unknown) and negative sizes: VTK reads 0 as 1 mm, and the size of
    // a negative one is its magnitude (as nibabel reads it; the direction is the qform's).
    const double p = f.pixdim[1 + a];
    d.spacing[a] = p == 0 ? 1.0 : std::fabs(p);
    const std::string name = path + ": pixdim[" + std::to_string(a + 1) + "] is " + numberShown(p);
    if (p == 0)
      d.notes.push_back(name +
                        " (unknown): read as 1 mm, as VTK does; --size-mm scales the object");
    else if (p < 0)
      d.notes.push_back(name + ": read as " + numberShown(-p) +
                        " mm (the voxel size is its magnitude)");
  }
  if (!niftiType(f.datatype, d.bytesPerValue, d.components))
    throw InputError(path + ": datatype " + std::to_string(f.datatype) +
                     " is not one VTK reads as real values (integers, float32/64, RGB); " +
                     kNiftiFix);
  if (f.bitpix != d.bytesPerValue * d.components * 8)
    throw InputError(path + ": bitpix " + std::to_string(f.bitpix) + " disagrees with datatype " +
                     std::to_string(f.datatype) + "; " + kNiftiFix);
}
}  // namespace

DeclaredVolume declaredNifti(const std::string& path) {
  // By its first bytes, as VTK's gzopen reads it: an uncompressed file named .nii.gz is read too.
  std::string magic(2, '\0');
  std::ifstream(path, std::ios::binary).read(magic.data(), 2);
  const bool gz = magic == "\x1f\x8b";
  const HeaderBytes header = niftiHeader(path, gz);
  const NiftiFields f = niftiFields(path, header);
  DeclaredVolume d;
  d.dataPath = path;
  niftiAxes(path, f, d);
  checkDeclaredVolume(path, d);  // sizes and bounds before counting values
  const double headerSize = header.at<std::int32_t>(0);
  if (!(f.voxOffset >= headerSize && f.voxOffset < 1e12))
    throw InputError(path + ": vox_offset " + numberShown(f.voxOffset) +
                     " does not point past the header; " + kNiftiFix);
  const double needed = valuesNeeded(d) * d.bytesPerValue;
  const double bytes =
      gz ? inflatedBytes(path, 0, f.voxOffset + needed, Compression::Gzip, fileBytes(path))
         : fileBytes(path);
  d.valuesPresent = valuesIn(bytes - f.voxOffset, d.bytesPerValue);
  checkDeclaredVolume(path, d);
  return d;
}

}  // namespace lucent::io
