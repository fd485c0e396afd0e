// A folder of DICOM slices (PS3.5: data elements, transfer syntaxes; PS3.10: the file's preamble)
// checked slice by slice before VTK's vtkDICOMImageReader, which trusts each file's Rows and
// Columns: a slice whose tags promise more pixels than it holds, or slices of different sizes,
// crash it or leave uninitialised memory in the volume. Tags are walked up to the pixel data.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "../../util/error.hpp"
#include "volume_headers.hpp"

namespace lucent::io {

namespace {
constexpr const char* kDicomFix = "give a folder holding the slices of one uncompressed series";
constexpr std::size_t kMaxSlices = 100000;

/// What lucent reads from one slice.
struct DicomSlice {
  double rows = -1, columns = -1, bitsAllocated = -1, samples = 1, frames = 1;
  double pixelBytes = -1, pixelBytesPresent = -1;
  double slope = 1, intercept = 0;  ///< Rescale Slope and Intercept
  /// VTK's reader makes float output when the rescale is not whole (RescaledImageDataIsFloat), and
  /// decides that from the last slice: every slice must agree.
  bool floatRescale() const {
    return slope != std::trunc(slope) || intercept != std::trunc(intercept);
  }
  double spacing[2] = {1, 1};
};

/// Walks a slice's data elements (PS3.5 section 7) over `bytes`, recording the tags of DicomSlice.
class DicomWalker {
 public:
  DicomWalker(const std::string& path, const std::string& bytes, double fileSize)
      : mPath(path), mBytes(bytes), mFileSize(fileSize) {}

  /// As VTK's DICOMParser::IsDICOMFile decides: "DICM" at byte 0 or 128, or a first group of
  /// 0002 or 0008. VTK's reader skips other files in the folder.
  static bool looksLikeDicom(const std::string& bytes) {
    if (bytes.compare(0, 4, "DICM") == 0) return true;
    if (bytes.size() >= 132 && bytes.compare(128, 4, "DICM") == 0) return true;
    if (bytes.size() < 8) return false;
    const unsigned group = unsigned((unsigned char)bytes[1]) << 8 | (unsigned char)bytes[0];
    return group == 0x0002 || group == 0x0008;
  }

  DicomSlice walk() {
    const bool at128 = mBytes.size() >= 132 && mBytes.compare(128, 4, "DICM") == 0;
    const bool at0 = mBytes.compare(0, 4, "DICM") == 0;
    mPos = at128 ? 132 : (at0 ? 4 : 0);
    // The meta group (0002) is explicit VR little endian, also in a file without the preamble.
    mExplicit = mPos + 8 <= mBytes.size() && u16(mPos) == 0x0002;
    std::string syntax = mExplicit ? "" : "1.2.840.10008.1.2";
    while (mPos + 8 <= mBytes.size() && u16(mPos) == 0x0002) element(0, &syntax);
    setSyntax(syntax);
    while (!mDone && mPos + 8 <= mBytes.size()) element(0, nullptr);
    if (!mDone)
      fail("has no pixel data (is it a DICOMDIR or a report?); move it out of the folder");
    // VTK's parser reads on past the pixel data to the end of the file and hands later tags to the
    // same callbacks (an empty Columns there crashed it: fuzz_scan_dicom): they are checked too.
    while (mPos + 8 <= mBytes.size()) element(0, nullptr);
    return mSlice;
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw InputError(mPath + ": " + why + "; " + kDicomFix);
  }
  std::uint16_t u16(std::size_t at) const {
    const auto* b = reinterpret_cast<const unsigned char*>(mBytes.data() + at);
    return mBig ? std::uint16_t(b[0] << 8 | b[1]) : std::uint16_t(b[1] << 8 | b[0]);
  }
  std::uint32_t u32(std::size_t at) const {
    return mBig ? std::uint32_t(u16(at)) << 16 | u16(at + 2)
                : std::uint32_t(u16(at + 2)) << 16 | u16(at);
  }

  void setSyntax(std::string uid) {
    uid.erase(std::find(uid.begin(), uid.end(), '\0'), uid.end());
    while (!uid.empty() && uid.back() == ' ') uid.pop_back();
    if (uid == "1.2.840.10008.1.2")
      mExplicit = false;
    else if (uid == "1.2.840.10008.1.2.1")
      mExplicit = true;
    else if (uid == "1.2.840.10008.1.2.2")
      mExplicit = true, mBig = true;
    else if (uid.empty())
      fail("has a meta header without a Transfer Syntax UID (0002,0010); re-export the series");
    else
      fail("is stored in transfer syntax " + printable(uid, 64) +
           " (compressed), which VTK's "
           "DICOM reader does not read; decompress it (gdcmconv --raw, dcmdjpeg)");
  }

  /// One element at mPos: its header, then its value (recorded, skipped or walked into).
  void element(int depth, std::string* syntax) {
    if (depth > kMaxDepth) fail("nests sequences more than 16 deep");
    const std::uint16_t group = u16(mPos), elem = u16(mPos + 2);
    std::size_t header = 8;
    std::uint32_t length = 0;
    const bool item = group == 0xFFFE;  // items and delimiters carry no VR
    if (mExplicit && !item) {           // a short-form element may end the file (8 bytes, no value)
      const std::string vr = mBytes.substr(mPos + 4, 2);
      const bool longForm = vr == "OB" || vr == "OW" || vr == "OF" || vr == "SQ" || vr == "UT" ||
                            vr == "UN" || vr == "OD" || vr == "OL" || vr == "UC" || vr == "UR" ||
                            vr == "OV" || vr == "SV" || vr == "UV";
      if (longForm && mPos + 12 > mBytes.size())
        fail("is truncated inside its tags (re-export the series)");
      length = longForm ? u32(mPos + 8) : u16(mPos + 6);
      header = longForm ? 12 : 8;
    } else {
      length = u32(mPos + 4);
    }
    mPos += header;
    checkReadByVtk(group, elem, length == 0xFFFFFFFF ? 0 : length);
    if (group == 0x7FE0 && elem == 0x0010) return pixelData(length, depth);
    if (length == 0xFFFFFFFF) return undefinedLength(depth);
    if (mPos + length > mBytes.size()) fail("is truncated inside its tags (re-export the series)");
    record(group, elem, mBytes.substr(mPos, length), syntax);
    mPos += length;
  }

  /// A sequence or item of undefined length: elements up to its delimiter (FFFE,E00D / E0DD).
  void undefinedLength(int depth) {
    if (depth > kMaxDepth) fail("nests sequences more than 16 deep");
    while (mPos + 8 <= mBytes.size()) {
      const std::uint16_t group = u16(mPos), elem = u16(mPos + 2);
      if (group == 0xFFFE && (elem == 0xE00D || elem == 0xE0DD)) {
        mPos += 8;
        return;
      }
      if (group == 0xFFFE && elem == 0xE000 && u32(mPos + 4) == 0xFFFFFFFF) {
        mPos += 8;
        undefinedLength(depth + 1);
        continue;
      }
      element(depth + 1, nullptr);
    }
    fail("is truncated inside a sequence (re-export the series)");
  }

  void pixelData(std::uint32_t length, int depth) {
    if (depth > 0) fail("has its pixel data inside a sequence");
    if (mDone) fail("has a second pixel data element");
    if (length == 0xFFFFFFFF)
      fail(
          "holds encapsulated (compressed) pixel data, which VTK's DICOM reader does not read; "
          "decompress it (gdcmconv --raw, dcmdjpeg)");
    mSlice.pixelBytes = length;  // VTK reads it into an int: 2^31 and above is negative there
    if (double(length) >= 2147483647.0) fail("declares 2 GB or more of pixel data in one slice");
    mSlice.pixelBytesPresent = mFileSize - double(mPos);
    mDone = true;
    const double end = double(mPos) + double(length);  // the tags after it are walked too
    if (end < mFileSize && end > double(mBytes.size()))
      fail("has tags after its pixel data beyond the first " +
           numberShown(double(mBytes.size()) / (1 << 20)) +
           " MB lucent reads of a slice");  // a 1 MB window is retried at 64 MB
    mPos = std::min(mBytes.size(), mPos + std::size_t(length));
  }

  void record(std::uint16_t group, std::uint16_t elem, const std::string& value,
              std::string* syntax) {
    const auto number = [&](double& out) {
      if (value.size() == 2)
        out = u16(mPos);
      else if (value.size() == 4)
        out = u32(mPos);
    };
    if (syntax && group == 0x0002 && elem == 0x0010) *syntax = value;
    if (group != 0x0028) return;
    if (elem == 0x0010) number(mSlice.rows);
    if (elem == 0x0011) number(mSlice.columns);
    if (elem == 0x0100) number(mSlice.bitsAllocated);
    if (elem == 0x0002) number(mSlice.samples);
    if (elem == 0x0008 && !parseNumber(value.substr(0, value.find('\0')), mSlice.frames))
      mSlice.frames = 1;
    if (elem == 0x1052 || elem == 0x1053) {  // Rescale Intercept, Slope: VTK casts them to int
      double v = NAN;
      const bool ok = parseNumber(value.substr(0, value.find('\0')), v) && std::fabs(v) < 2e9;
      (elem == 0x1053 ? mSlice.slope : mSlice.intercept) = ok ? v : NAN;
    }
    if (elem == 0x0030) {  // Pixel Spacing "row\column"
      const auto slash = value.find('\\');
      double r = 0, c = 0;
      if (slash != std::string::npos && parseNumber(value.substr(0, slash), r) &&
          parseNumber(value.substr(slash + 1, value.find('\0') - slash - 1), c))
        mSlice.spacing[0] = c, mSlice.spacing[1] = r;
      else
        mSlice.spacing[0] = mSlice.spacing[1] = NAN;
    }
  }

  /// The tags VTK's DICOMAppHelper hands to its callbacks, which read the value without looking at
  /// its length: an empty one is a null pointer there (found by fuzz_scan_dicom), a 1-byte
  /// unsigned short a read past it.
  void checkReadByVtk(std::uint16_t group, std::uint16_t elem, std::size_t length) const {
    struct Tag {
      std::uint16_t group, elem;
      std::size_t minLength;
      const char* name;
    };
    static constexpr Tag kRead[] = {{0x0002, 0x0010, 1, "Transfer Syntax UID"},
                                    {0x0018, 0x0050, 1, "Slice Thickness"},
                                    {0x0020, 0x000E, 1, "Series Instance UID"},
                                    {0x0020, 0x0013, 1, "Instance Number"},
                                    {0x0020, 0x0032, 1, "Image Position"},
                                    {0x0020, 0x0037, 1, "Image Orientation"},
                                    {0x0020, 0x1041, 1, "Slice Location"},
                                    {0x0028, 0x0004, 1, "Photometric Interpretation"},
                                    {0x0028, 0x0010, 2, "Rows"},
                                    {0x0028, 0x0011, 2, "Columns"},
                                    {0x0028, 0x0030, 1, "Pixel Spacing"},
                                    {0x0028, 0x0100, 2, "Bits Allocated"},
                                    {0x0028, 0x0103, 2, "Pixel Representation"},
                                    {0x0028, 0x1052, 1, "Rescale Intercept"},
                                    {0x0028, 0x1053, 1, "Rescale Slope"},
                                    {0x0018, 0x1120, 4, "Gantry Tilt"}};
    for (const Tag& t : kRead)
      if (t.group == group && t.elem == elem && length < t.minLength)
        fail(std::string("has ") + (length ? "a cut " : "an empty ") + t.name +
             " tag, which VTK's DICOM reader cannot take (re-export the series)");
  }

  static constexpr int kMaxDepth = 16;
  const std::string& mPath;
  const std::string& mBytes;
  double mFileSize;
  std::size_t mPos = 0;
  bool mExplicit = false, mBig = false, mDone = false;
  DicomSlice mSlice;
};
}  // namespace

namespace {
/// Reads and walks one slice: its tags are within its first megabyte, or else its first 64.
DicomSlice readSlice(const std::string& path) {
  const double size = fileBytes(path);
  for (const double window : {1 << 20, 64 << 20}) {
    std::ifstream in(path, std::ios::binary);
    std::string bytes(std::size_t(std::min(size, window)), '\0');
    in.read(bytes.data(), std::streamsize(bytes.size()));
    try {
      return DicomWalker(path, bytes, size).walk();
    } catch (const InputError&) {
      if (size <= window || window > (1 << 20)) throw;  // the whole file was walked
    }
  }
  return {};
}

/// One slice's own promises: the sizes VTK reads and as many pixel bytes as they need.
void checkSlice(const std::string& path, const DicomSlice& s) {
  const auto fail = [&](const std::string& why) {
    throw InputError(path + ": " + why + "; " + kDicomFix);
  };
  if (!(s.rows >= 1 && s.columns >= 1)) fail("has no Rows or Columns tag, or one of 0");
  if (!(s.spacing[0] > 0 && s.spacing[1] > 0))
    fail("has a Pixel Spacing of " + numberShown(s.spacing[1]) + "\\" + numberShown(s.spacing[0]) +
         " (two positive numbers are needed)");
  if (s.bitsAllocated != 8 && s.bitsAllocated != 16)
    fail("has BitsAllocated " + numberShown(s.bitsAllocated) +
         " (VTK's DICOM reader reads 8 or 16)");
  if (s.samples != 1)
    fail("has " + numberShown(s.samples) + " samples per pixel (colour); lucent reads greyscale");
  if (s.frames != 1)
    fail("holds " + numberShown(s.frames) +
         " frames, and VTK's DICOM reader reads one per file; "
         "split it into single-frame slices (gdcmconv --split-frames... or dcmconv)");
  const double needed = s.rows * s.columns * s.bitsAllocated / 8;
  if (s.pixelBytes < needed)
    fail("promises " + numberShown(s.rows) + " x " + numberShown(s.columns) + " pixels (" +
         numberShown(needed) + " bytes) but its pixel data is " + numberShown(s.pixelBytes) +
         " bytes long");
  if (!std::isfinite(s.slope) || !std::isfinite(s.intercept))
    fail("has a Rescale Slope or Intercept that is not a number within +-2e9");
  if (s.pixelBytes > s.pixelBytesPresent)
    fail("is truncated: its pixel data is " + numberShown(s.pixelBytes) +
         " bytes, the file holds " + numberShown(std::max(0.0, s.pixelBytesPresent)));
  if (s.pixelBytesPresent < needed)
    fail("is truncated: its pixel data needs " + numberShown(needed) + " bytes, the file holds " +
         numberShown(std::max(0.0, s.pixelBytesPresent)));
}
}  // namespace

namespace {
/// The folder's files VTK's reader takes as slices, sorted; `skipped` names the others.
std::vector<std::string> sliceFiles(const std::string& folder, std::vector<std::string>& skipped) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    if (files.size() + skipped.size() == kMaxSlices)
      throw InputError(folder + ": holds more than 100000 files; " + kDicomFix);
    std::ifstream in(entry.path(), std::ios::binary);
    std::string head(132, '\0');
    in.read(head.data(), 132);
    head.resize(std::size_t(in.gcount()));
    (DicomWalker::looksLikeDicom(head) ? files : skipped).push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  if (files.size() < 2)
    throw InputError(
        folder + ": holds " + std::to_string(files.size()) +
        " DICOM file(s); a DICOM volume is a folder of at least 2 slices: " + kDicomFix);
  return files;
}
}  // namespace

DeclaredVolume declaredDicomSeries(const std::string& folder) {
  DeclaredVolume d;
  d.dataPath = folder;
  std::vector<std::string> skipped;
  const std::vector<std::string> files = sliceFiles(folder, skipped);
  for (const std::string& file : skipped)
    d.notes.push_back(file + " is not a DICOM file; VTK's reader skips it, and so does lucent");
  const DicomSlice first = readSlice(files.front());
  for (const std::string& file : files) {
    const DicomSlice s = file == files.front() ? first : readSlice(file);
    checkSlice(file, s);
    if (s.rows != first.rows || s.columns != first.columns ||
        s.bitsAllocated != first.bitsAllocated)
      throw InputError(file + ": is " + numberShown(s.columns) + " x " + numberShown(s.rows) +
                       " pixels of " + numberShown(s.bitsAllocated) + " bits, " + files.front() +
                       " is " + numberShown(first.columns) + " x " + numberShown(first.rows) +
                       " of " + numberShown(first.bitsAllocated) + "; " + kDicomFix);
    if (s.floatRescale() != first.floatRescale())
      throw InputError(file + ": its Rescale Slope/Intercept is " +
                       (s.floatRescale() ? "fractional" : "whole") + ", that of " + files.front() +
                       " is not, and VTK's reader sizes the volume from one of them; " + kDicomFix);
  }
  d.dims = {first.columns, first.rows, double(files.size())};
  d.bytesPerValue = first.bitsAllocated / 8;
  d.spacing = {first.spacing[0], first.spacing[1], 1};  // VTK finds z from the slices' positions
  d.valuesPresent = valuesNeeded(d);                    // each slice was checked whole
  checkDeclaredVolume(folder, d);
  return d;
}

}  // namespace lucent::io
