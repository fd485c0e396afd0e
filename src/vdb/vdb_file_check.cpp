#include "vdb_file_check.hpp"

#include <cstdint>
#include <filesystem>
#include <fstream>

#include "../util/error.hpp"

namespace lucent::vdb {

namespace {
constexpr std::uint64_t kMagic = 0x56444220;  // "VDB " as OpenVDB writes it, little-endian int64
constexpr std::uint32_t kFirstCheckedVersion =
    222;  // per-grid compression, grid offsets (OpenVDB 3)
constexpr int kUuidChars = 36;

/// Little-endian fields read with the bytes left checked before each one.
class BoundedReader {
 public:
  explicit BoundedReader(const std::string& path)
      : mPath(path), mIn(path, std::ios::binary), mSize(std::filesystem::file_size(path)) {}

  std::uint64_t size() const { return mSize; }
  std::uint64_t at() const { return mAt; }
  void seek(std::uint64_t offset) {
    mAt = offset;
    mIn.seekg(std::streamoff(offset));
  }

  std::uint64_t u64(const char* what) { return field(8, what); }
  std::uint32_t u32(const char* what) { return std::uint32_t(field(4, what)); }
  std::uint8_t u8(const char* what) { return std::uint8_t(field(1, what)); }
  /// Skips `n` bytes that `what` declares, after checking they are there.
  void skip(std::uint64_t n, const std::string& what) {
    if (n > mSize - mAt)
      fail(what + " declares " + std::to_string(n) + " bytes at offset " + std::to_string(mAt) +
           ", but only " + std::to_string(mSize - mAt) + " are left");
    seek(mAt + n);
  }
  void string(const std::string& what) { skip(u32(what.c_str()), what); }

  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError("cannot read '" + mPath + "' as OpenVDB: " + problem +
                     "; the file is truncated or corrupt (re-export it)");
  }

 private:
  std::uint64_t field(int bytes, const char* what) {
    if (std::uint64_t(bytes) > mSize - mAt)
      fail(std::string("the file ends inside ") + what + " (offset " + std::to_string(mAt) + ")");
    unsigned char b[8] = {};
    mIn.read(reinterpret_cast<char*>(b), bytes);
    mAt += std::uint64_t(bytes);
    std::uint64_t v = 0;
    for (int i = bytes - 1; i >= 0; --i) v = v << 8 | b[i];
    return v;
  }

  const std::string& mPath;
  std::ifstream mIn;
  std::uint64_t mSize, mAt = 0;
};

/// A metadata map: a count, then per entry a name, a type name and a sized value.
void checkMetadata(BoundedReader& in, const std::string& owner) {
  const std::uint32_t count = in.u32("a metadata count");
  constexpr std::uint64_t kSmallestEntry = 12;  // three lengths
  if (std::uint64_t(count) * kSmallestEntry > in.size() - in.at())
    in.fail(owner + " declares " + std::to_string(count) + " metadata entries, more than fit");
  for (std::uint32_t i = 0; i < count; ++i) {
    in.string(owner + "'s metadata name");
    in.string(owner + "'s metadata type");
    in.skip(in.u32("a metadata size"), owner + "'s metadata value");
  }
}

void checkGrid(BoundedReader& in, std::uint32_t index) {
  const std::string grid = "grid " + std::to_string(index);
  in.string(grid + "'s name");
  in.string(grid + "'s type");
  in.string(grid + "'s instance parent");
  const std::uint64_t start = in.at();
  const std::uint64_t gridPos = in.u64("a grid offset"), blockPos = in.u64("a grid offset"),
                      endPos = in.u64("a grid offset");
  if (!(start < gridPos && gridPos <= blockPos && blockPos <= endPos && endPos <= in.size()))
    in.fail(grid + "'s offsets (" + std::to_string(gridPos) + ", " + std::to_string(blockPos) +
            ", " + std::to_string(endPos) + ") do not lie in order inside the file's " +
            std::to_string(in.size()) + " bytes");
  in.seek(gridPos);
  in.u32("a grid's compression flags");
  checkMetadata(in, grid);
  in.string(grid + "'s transform type");
  in.seek(endPos);
}
}  // namespace

void checkVdbLayout(const std::string& path) {
  BoundedReader in(path);
  if (in.size() < 8 || in.u64("the magic number") != kMagic)
    in.fail("it does not start with OpenVDB's magic number (is it a .vdb file?)");
  const std::uint32_t version = in.u32("the file version");
  if (version < kFirstCheckedVersion)
    in.fail("file format " + std::to_string(version) +
            " predates OpenVDB 3 (222); re-save it with a current OpenVDB");
  in.u32("the library version"), in.u32("the library version");
  if (in.u8("the grid-offsets flag") == 0)
    in.fail("it was written as a stream without grid offsets; re-save it as a file");
  in.skip(kUuidChars, "the file's UUID");
  checkMetadata(in, "the file");
  const std::uint32_t grids = in.u32("the grid count");
  constexpr std::uint64_t kSmallestGrid = 12 + 24;  // three lengths, three offsets
  if (std::uint64_t(grids) * kSmallestGrid > in.size() - in.at())
    in.fail("it declares " + std::to_string(grids) + " grids, more than fit");
  for (std::uint32_t g = 0; g < grids; ++g) checkGrid(in, g);
}

}  // namespace lucent::vdb
