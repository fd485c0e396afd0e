#pragma once
/// @file atomic_file.hpp
/// @brief Write to "<path>.tmp-<pid>", rename onto <path> on commit(); remove the temporary otherwise.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "../util/error.hpp"

namespace lucent::io {

class AtomicFile {
 public:
  explicit AtomicFile(std::string path) : mPath(std::move(path)) {
    const std::filesystem::path parent = std::filesystem::path(mPath).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent))
      throw InputError("cannot write '" + mPath + "': folder '" + parent.string() + "' does not exist; create it first");
    mTemp = mPath + ".tmp-" + std::to_string(::getpid());
  }
  ~AtomicFile() {
    if (!mCommitted) {
      std::error_code ec;
      std::filesystem::remove(mTemp, ec);
    }
  }
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& tempPath() const { return mTemp; }
  void commit() {
    std::error_code ec;
    std::filesystem::rename(mTemp, mPath, ec);
    if (ec) throw InputError("cannot write '" + mPath + "': " + ec.message());
    mCommitted = true;
  }

 private:
  std::string mPath, mTemp;
  bool mCommitted = false;
};

/// Writes a whole text file atomically; throws InputError naming the file on failure.
inline void writeTextFile(const std::string& path, const std::string& text) {
  AtomicFile out(path);
  {
    std::ofstream f(out.tempPath());
    f << text;
    if (!f) throw InputError("cannot write '" + path + "': check free space and permissions");
  }
  out.commit();
}

}  // namespace lucent::io
