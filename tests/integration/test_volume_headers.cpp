// lucent's own checks of volume headers before VTK's readers (src/io/volume_headers/): the cases a
// reliability probe found crashing VTK's readers (a signal), allocating without bound (exit 1) or
// reading garbage (exit 0), each replayed through the CLI: exit 2 with one line naming the file,
// the problem and a fix, nothing written. And sound files of every format still render.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "io/vtk_volume.hpp"
#include "temp_dir.hpp"
#include "volume_files.hpp"

namespace {
using lucent::test::contains;
using lucent::test::lucentCli;
using lucent::test::Run;
using namespace lucent::test;

/// One probe case: the files it writes into a folder, the volume argument, what the error names.
struct ProbeCase {
  const char* name;
  std::function<std::string(const TempDir&)> write;  ///< returns the --volume argument
  const char* expected;                              ///< a part of the one-line error
};

std::string nrrd(const TempDir& dir, const std::string& fields, const std::string& data) {
  writeFile(dir / "v.nrrd", "NRRD0004\n" + fields + "\n" + data);
  return dir / "v.nrrd";
}

std::string meta(const TempDir& dir, const std::string& keys, const std::string& data) {
  writeFile(dir / "v.mha", keys + "ElementDataFile = LOCAL\n" + data);
  return dir / "v.mha";
}

/// A DICOM folder of `n` slices of the 16^3 ball; `change(k, slice)` may spoil slice k.
std::string dicom(const TempDir& dir, int n, const std::function<void(int, std::string&)>& change) {
  std::filesystem::create_directories(dir / "series");
  for (int k = 0; k < n; ++k) {
    std::string s = dicomSlice(k, 16, 16, ballSlice(16, k));
    change(k, s);
    writeFile(dir / ("series/slice" + std::to_string(100 + k) + ".dcm"), s);
  }
  return dir / "series";
}

const std::string kBall = bytesOf(ballVoxels(16));
const std::string kRaw = "type: ushort\nencoding: raw\nendian: little\n";
const std::string kMeta = "ObjectType = Image\nElementType = MET_USHORT\n";

const std::vector<ProbeCase> kProbeCases = {
    {"NRRD dimension 0",
     [](auto& d) { return nrrd(d, kRaw + "dimension: 0\nsizes: 16 16 16\n", kBall); },
     "'dimension: 0'"},
    {"NRRD dimension 1",
     [](auto& d) { return nrrd(d, kRaw + "dimension: 1\nsizes: 4096\n", kBall); },
     "'dimension: 1'"},
    {"NRRD dimension 5",
     [](auto& d) { return nrrd(d, kRaw + "dimension: 5\nsizes: 1 16 16 16 1\n", kBall); },
     "'dimension: 5'"},
    {"NRRD negative size",
     [](auto& d) { return nrrd(d, kRaw + "dimension: 3\nsizes: -16 16 16\n", kBall); },
     "declares -16 voxels along x"},
    {"NRRD sizes of 1e12",
     [](auto& d) { return nrrd(d, kRaw + "dimension: 3\nsizes: 999999999999 16 16\n", kBall); },
     "more than lucent reads"},
    {"NRRD zero spacing",
     [](auto& d) {
       return nrrd(d, kRaw + "dimension: 3\nsizes: 16 16 16\nspacings: 0 1 1\n", kBall);
     },
     "spacing along x is 0"},
    {"NRRD 500^3 floats in 16 KB",
     [](auto& d) {
       return nrrd(d, "type: float\nencoding: raw\ndimension: 3\nsizes: 500 500 500\n",
                   std::string(16000, 'x'));
     },
     "of the 125000000 values"},
    {"NRRD corrupt gzip",
     [](auto& d) {
       return nrrd(d, "type: ushort\nencoding: gzip\ndimension: 3\nsizes: 16 16 16\n",
                   "\x1f\x8b\x08garbage-not-deflate");
     },
     "compressed data is corrupt"},
    {"NRRD header only",
     [](auto& d) {
       writeFile(d / "v.nrrd", "NRRD0004\n" + kRaw + "dimension: 3\nsizes: 16 16 16\n");
       return d / "v.nrrd";
     },
     "neither ends in a blank line"},
    {"NRRD detached header whose last line has no newline (VTK 9.1 repeats it forever)",
     [](auto& d) {
       writeFile(d / "v.raw", kBall);
       writeFile(d / "v.nhdr",
                 "NRRD0004\n" + kRaw + "dimension: 3\nsizes: 16 16 16\ndata file: v.raw");
       return d / "v.nhdr";
     },
     "has no newline (VTK's reader would hang on it)"},
    {"NRRD magic line with NUL bytes (a fuzz_scan_nrrd hang: VTK's header text ends at the NUL)",
     [](auto& d) {
       writeFile(d / "v.nrrd", std::string("NRRD\x0e\0\0\0\0\0\0\0"
                                           "0004\n",
                                           17) +
                                   kRaw + "dimension: 3\nsizes: 16 16 16\n\n" + kBall);
       return d / "v.nrrd";
     },
     "holds a NUL byte"},
    {"NRRD missing data file",
     [](auto& d) {
       return nrrd(d, kRaw + "dimension: 3\nsizes: 16 16 16\ndata file: gone.raw\n", "");
     },
     "gone.raw: no such file"},
    {"NRRD unknown type",
     [](auto& d) { return nrrd(d, "type: block\ndimension: 3\nsizes: 16 16 16\n", kBall); },
     "'type: block'"},
    {"MetaImage NDims 4",
     [](auto& d) { return meta(d, kMeta + "NDims = 4\nDimSize = 16 16 16 1\n", kBall); },
     "'NDims = 4'"},
    {"MetaImage NDims 5",
     [](auto& d) { return meta(d, kMeta + "NDims = 5\nDimSize = 16 16 16 1 1\n", kBall); },
     "'NDims = 5'"},
    {"MetaImage -3 channels",
     [](auto& d) {
       return meta(d, kMeta + "NDims = 3\nDimSize = 16 16 16\nElementNumberOfChannels = -3\n",
                   kBall);
     },
     "-3 values per voxel"},
    {"MetaImage 100000 channels",
     [](auto& d) {
       return meta(d,
                   kMeta + "NDims = 3\nDimSize = 100 100 100\nElementNumberOfChannels = 100000\n",
                   std::string(4000, 'x'));
     },
     "100000 values per voxel"},
    {"MetaImage CompressedDataSize 99999999999",
     [](auto& d) {
       return meta(d,
                   kMeta +
                       "NDims = 3\nDimSize = 16 16 16\nCompressedData = True\nCompressedDataSize = "
                       "99999999999\n",
                   kBall);
     },
     "'CompressedDataSize = 99999999999'"},
    {"MetaImage zero spacing (VTK reads 0: a flat volume; a negative one is read as its magnitude)",
     [](auto& d) {
       return meta(d, kMeta + "NDims = 3\nDimSize = 16 16 16\nElementSpacing = 1 0 1\n", kBall);
     },
     "spacing along y is 0"},
    {"MetaImage 500^3 floats in 16 KB",
     [](auto& d) {
       return meta(d, "ElementType = MET_FLOAT\nNDims = 3\nDimSize = 500 500 500\n",
                   std::string(16000, 'x'));
     },
     "of the 125000000 values"},
    {"MetaImage unparsable header",
     [](auto& d) {
       writeFile(d / "v.mha", "this is not a header\n");
       return d / "v.mha";
     },
     "is not a MetaImage 'Key = Value' line"},
    {"NIfTI unknown datatype",
     [](auto& d) {
       writeFile(d / "v.nii", niftiHeader(16, 16, 16, 4242, 16) + kBall);
       return d / "v.nii";
     },
     "datatype 4242"},
    {"NIfTI time series",
     [](auto& d) {
       writeFile(d / "v.nii", niftiHeader(16, 16, 16, 512, 16, 4, 3) + kBall);
       return d / "v.nii";
     },
     "holds 3 volumes"},
    {"NIfTI truncated",
     [](auto& d) {
       writeFile(d / "v.nii", niftiHeader(16, 16, 16) + kBall.substr(0, 100));
       return d / "v.nii";
     },
     "of the 4096 values"},
    {"NIfTI shorter than its header",
     [](auto& d) {
       writeFile(d / "v.nii.gz", gzipped("tiny"));
       return d / "v.nii.gz";
     },
     "shorter than a NIfTI header"},
    {"DICOM slices of two sizes",
     [](auto& d) {
       return dicom(d, 16, [](int k, std::string& s) {
         if (k == 5) s = dicomSlice(k, 32, 32, std::string(2048, '\0'));
       });
     },
     "is 32 x 32 pixels"},
    {"DICOM Rows 65535",
     [](auto& d) {
       return dicom(d, 16, [](int k, std::string& s) {
         if (k == 3) s = dicomSlice(k, 65535, 16, ballSlice(16, k));
       });
     },
     "promises 65535 x 16 pixels"},
    {"DICOM truncated slice",
     [](auto& d) {
       return dicom(d, 16, [](int k, std::string& s) {
         if (k == 7) s.resize(s.size() - 300);
       });
     },
     "is truncated"},
    {"DICOM compressed",
     [](auto& d) {
       return dicom(d, 4, [](int, std::string& s) {
         const auto at = s.find("1.2.840.10008.1.2.1");
         s.replace(at, 19, "1.2.840.10008.1.2.4");
       });
     },
     "(compressed)"},
    {"NRRD ascii (VTK reads the header as values)",
     [](auto& d) {
       return nrrd(d, "type: ushort\nencoding: ascii\ndimension: 3\nsizes: 2 2 10\n", "1 2 3");
     },
     "is misread by VTK's reader"},
    {"NRRD size 1e2 (VTK's atoi reads 1)",
     [](auto& d) { return nrrd(d, kRaw + "dimension: 3\nsizes: 1e2 16 16\n", kBall); },
     "'sizes: 1e2 16 16' are not whole decimal numbers"},
    {"NRRD dimension after sizes",
     [](auto& d) { return nrrd(d, kRaw + "sizes: 16 16 16\ndimension: 3\n", kBall); },
     "comes after 'sizes'"},
    {"MetaImage MET_LONG_LONG (VTK sizes the output to one voxel)",
     [](auto& d) {
       return meta(d, "ElementType = MET_LONG_LONG\nNDims = 3\nDimSize = 16 16 16\n", kBall);
     },
     "'ElementType = MET_LONG_LONG'"},
    {"MetaImage key given twice",
     [](auto& d) { return meta(d, kMeta + "NDims = 3\nNDims = 3\nDimSize = 16 16 16\n", kBall); },
     "the key NDims is given twice"},
    {"MetaImage HeaderSize past the file",
     [](auto& d) {
       return meta(d, kMeta + "NDims = 3\nDimSize = 16 16 16\nHeaderSize = 99999999\n", kBall);
     },
     "'HeaderSize = 99999999'"},
    {"MetaImage compressed LOCAL without CompressedDataSize",
     [](auto& d) {
       return meta(d, kMeta + "NDims = 3\nDimSize = 16 16 16\nCompressedData = True\n",
                   zlibbed(kBall));
     },
     "needs CompressedDataSize"},
    {"NRRD spacing 1e20 on one axis (the isosurface degenerates)",
     [](auto& d) {
       return nrrd(d, kRaw + "dimension: 3\nsizes: 16 16 16\nspacings: 1e20 1 1\n", kBall);
     },
     "spacing along x is 1e+20; spacing must lie in"},
    {"NRRD spacings 1000x apart",
     [](auto& d) {
       return nrrd(d, kRaw + "dimension: 3\nsizes: 16 16 16\nspacings: 0.01 1 20\n", kBall);
     },
     "differs more than 1000x between axes"},
    {"NRRD unknown field (a typo)",
     [](auto& d) {
       return nrrd(d, kRaw + "dimension: 3\nsizes: 16 16 16\nspacing: 1 1 1\n", kBall);
     },
     "'spacing: 1 1 1' is not a NRRD field"},
    {"NRRD header line with a NUL and control bytes",
     [](auto& d) {
       return nrrd(d, kRaw + std::string("dimension: 3\nsizes: 16\x00\x01 16 16\n", 31), kBall);
     },
     "'sizes: 16?? 16 16' holds a NUL byte"},
    {"DICOM empty Pixel Representation",
     [](auto& d) {
       return dicom(d, 4, [](int, std::string& s) {
         const std::string tag("\x28\x00\x03\x01US\x02\x00\x00\x00", 10);
         const auto at = s.find(tag);
         s.replace(at, tag.size(), std::string("\x28\x00\x03\x01US\x00\x00", 8));
       });
     },
     "has an empty Pixel Representation tag"},
    {"DICOM empty Columns after the pixel data (VTK's parser reads on to the end: fuzz_scan_dicom)",
     [](auto& d) {
       return dicom(d, 4, [](int k, std::string& s) {
         if (k == 2) s += std::string("\x28\x00\x11\x00US\x00\x00", 8);
       });
     },
     "has an empty Columns tag"},
};
}  // namespace

TEST_CASE(
    "Broken volume headers (the reliability probe's cases) exit 2 naming the file, problem "
    "and fix, with no VTK lines and nothing written") {
  for (const ProbeCase& c : kProbeCases) {
    TempDir dir;
    const std::string volume = c.write(dir);
    const Run r = lucentCli(
        "render --volume " + volume + " --iso 50 --width 8 --height 8 --out " + dir / "o.png", dir);
    INFO(std::string(c.name) << ": exit " << r.code << ", stderr: " << r.err);
    CHECK(r.code == 2);
    CHECK(contains(r.err, c.expected));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);  // one line, VTK's silenced
    CHECK_FALSE(std::filesystem::exists(dir / "o.png"));
  }
}

TEST_CASE(
    "Sound volumes of every checked format read back the values written: NRRD raw and gzip, "
    "MetaImage plain and zlib-compressed, NIfTI-1 plain and gzipped, a DICOM folder") {
  const std::vector<std::pair<const char*, std::function<std::string(const TempDir&)>>> sound = {
      {"NRRD raw",
       [](auto& d) {
         return nrrd(d, kRaw + "dimension: 3\nsizes: 16 16 16\nspacings: 1 1 1.5\n", kBall);
       }},
      {"NRRD gzip",
       [](auto& d) {
         return nrrd(
             d, "type: ushort\nencoding: gzip\nendian: little\ndimension: 3\nsizes: 16 16 16\n",
             gzipped(kBall));
       }},
      {"MetaImage",
       [](auto& d) {
         return meta(d, kMeta + "NDims = 3\nDimSize = 16 16 16\nElementSpacing = 1 1 1\n", kBall);
       }},
      {"MetaImage compressed",
       [](auto& d) {
         const std::string z = zlibbed(kBall);
         return meta(d,
                     kMeta +
                         "NDims = 3\nDimSize = 16 16 16\nCompressedData = True\n"
                         "CompressedDataSize = " +
                         std::to_string(z.size()) + "\n",
                     z);
       }},
      {"NIfTI-1",
       [](auto& d) {
         writeFile(d / "v.nii", niftiHeader(16, 16, 16) + kBall);
         return d / "v.nii";
       }},
      {"NIfTI-1 gzipped",
       [](auto& d) {
         writeFile(d / "v.nii.gz", gzipped(niftiHeader(16, 16, 16) + kBall));
         return d / "v.nii.gz";
       }},
      {"DICOM folder", [](auto& d) { return dicom(d, 16, [](int, std::string&) {}); }},
  };
  const std::vector<std::uint16_t> ball = ballVoxels(16);  // symmetric: any axis order reads alike
  for (const auto& entry : sound) {
    const auto& name = std::get<0>(entry);  // no structured binding: clang 14 cannot capture one
    const auto& write = std::get<1>(entry);
    TempDir dir;
    INFO(name);
    const lucent::scene::VoxelGrid grid = lucent::io::readImageVolume(write(dir));
    REQUIRE(grid.values.size() == ball.size());
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < ball.size(); ++i) wrong += grid.values[i] != float(ball[i]);
    CHECK(wrong == 0);
  }
}

TEST_CASE(
    "A DICOM folder holding a file that is not DICOM: skipped as VTK's reader skips it, "
    "and said so") {
  TempDir dir;
  const std::string folder = dicom(dir, 16, [](int k, std::string& s) {
    if (k == 9) s = std::string(600, 'g');
  });
  const Run r = lucentCli(
      "render --volume " + folder +
          " --iso 50 --method voxel-single --width 8 --height 8 --quiet --out " + dir / "o.png",
      dir);
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK(contains(r.err, "slice109.dcm is not a DICOM file; VTK's reader skips it"));
}

TEST_CASE(
    "Spacings real files carry: NIfTI pixdim 0 (unknown) read as 1 mm and a negative pixdim as "
    "its magnitude, MetaImage negative spacing as VTK reads it, each with a note") {
  const auto niftiWithPixdim = [](const TempDir& d, float x, float y, float z) {
    std::string h = niftiHeader(16, 16, 16);
    const float pixdim[3] = {x, y, z};
    std::memcpy(&h[80], pixdim, sizeof pixdim);  // pixdim[1..3]
    writeFile(d / "v.nii", h + kBall);
    return d / "v.nii";
  };
  {
    TempDir dir;
    const auto grid = lucent::io::readImageVolume(niftiWithPixdim(dir, 0, 0, 0));
    CHECK(grid.spacing == glm::dvec3(1, 1, 1));
  }
  {
    TempDir dir;
    const auto grid = lucent::io::readImageVolume(niftiWithPixdim(dir, -0.5, 0.5, 2));
    CHECK(grid.spacing == glm::dvec3(0.5, 0.5, 2));
  }
  {
    TempDir dir;
    const auto grid = lucent::io::readImageVolume(
        meta(dir, kMeta + "NDims = 3\nDimSize = 16 16 16\nElementSpacing = 1 -2 1\n", kBall));
    CHECK(grid.spacing == glm::dvec3(1, 2, 1));
  }
  TempDir dir;
  const Run r = lucentCli(
      "render --volume " + niftiWithPixdim(dir, 0, 0, 0) +
          " --iso 50 --method voxel-single --width 8 --height 8 --quiet --out " + dir / "o.png",
      dir);
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK(contains(r.err, "pixdim[1] is 0 (unknown): read as 1 mm, as VTK does"));
}
