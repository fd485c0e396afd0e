#pragma once
/// @file declared_volume.hpp
/// @brief What a volume file declares, read by lucent before any VTK reader allocates or parses its
/// values, and the one set of checks every format shares (sizes, components, a bound in bytes,
/// spacing, values present). VTK's image readers trust their headers: a negative size, a fourth
/// dimension or a slice shorter than its Rows tag crashes them or reads uninitialised memory.
#include <array>
#include <istream>
#include <string>
#include <vector>

#include "../voxel_bound.hpp"  // numberShown

namespace lucent::io {

/// Values as stored, all components: what a reader allocates before lucent converts them to its
/// float grid (scene::kMaxVoxels bounds that grid). 4 GB: a 1024^3 scan of 32-bit values.
inline constexpr double kMaxVolumeBytes = 4e9;

/// Values per voxel lucent takes (a scalar, a vector, RGB(A)); more are a time series or a tensor.
inline constexpr double kMaxVolumeComponents = 4;

/// A volume as its header declares it. Numbers are doubles: a hostile header's exceed int.
struct DeclaredVolume {
  std::array<double, 3> dims{0, 0, 0};     ///< voxels along x, y, z
  double components = 1;                   ///< values per voxel
  double bytesPerValue = 0;                ///< of the stored type
  std::array<double, 3> spacing{1, 1, 1};  ///< voxel size along x, y, z
  std::string dataPath;                    ///< the file holding the values (may be the header's)
  double valuesPresent = -1;       ///< values the data holds (counted up to those needed); kUnknown
  std::vector<std::string> notes;  ///< what was accepted with a remark (a skipped file)
};

/// DeclaredVolume::valuesPresent when the data cannot be counted before reading.
inline constexpr double kUnknown = -1;

/// The values `declared` needs: dims x components.
double valuesNeeded(const DeclaredVolume& declared);

/// Throws InputError "<path>: <problem>; <fix>" unless `declared` is a 3-D volume lucent can read:
/// whole sizes of at least 1, at most scene::kMaxVoxels voxels and kMaxVolumeBytes bytes, 1 to
/// kMaxVolumeComponents components, finite positive spacing (one rule for every format), and as
/// many values present as declared.
void checkDeclaredVolume(const std::string& path, const DeclaredVolume& declared);

/// The fix every header problem shares.
inline constexpr const char* kReexportFix =
    "fix the header, or re-export the scan (e.g. ParaView: File > Save Data as .vti)";

/// Parses `text` as a finite number (the whole token); false when it is not one.
bool parseNumber(const std::string& text, double& value);

/// Reads one line of at most `maxBytes` into `line` (without its newline); false at the end of
/// the stream; InputError naming `path` when the line is longer (a header is never that long).
bool headerLine(std::istream& in, std::string& line, const std::string& path,
                std::size_t maxBytes = 65536);

/// Header text as a message may quote it: at most `max` characters, control and non-ASCII bytes
/// as '?' (a NUL cut the message short, raw control bytes reached the terminal).
std::string printable(const std::string& text, std::size_t max = 60);

/// `s` without leading and trailing blanks (spaces, tabs, a carriage return).
std::string trimmed(const std::string& s);

/// The whitespace-separated words of `s`.
std::vector<std::string> words(const std::string& s);

/// Bytes in the file at `path`; InputError naming `path` when it cannot be read.
double fileBytes(const std::string& path);

/// Whole values in `bytes` (0 for a negative count: data that starts past the end).
double valuesIn(double bytes, double bytesPerValue);

enum class Compression { Gzip, Zlib };

/// Bytes the compressed data starting `offset` bytes into `path` inflates to (gzip: all members;
/// zlib: one stream, of at most `inputLimit` compressed bytes), counting at most `limit`;
/// InputError naming the file when the data is corrupt or of another kind.
double inflatedBytes(const std::string& path, double offset, double limit, Compression kind,
                     double inputLimit);

/// The first `count` inflated bytes of the gzip file `path` (fewer when it is shorter).
std::string inflatedPrefix(const std::string& path, std::size_t count);

/// Whitespace-separated tokens from `offset` into `path`, counting at most `limit`: the values of
/// a text-encoded volume.
double textTokens(const std::string& path, double offset, double limit);

/// `name` resolved against the folder of `headerPath` (detached data files are named relative to
/// their header).
std::string besideHeader(const std::string& headerPath, const std::string& name);

}  // namespace lucent::io
