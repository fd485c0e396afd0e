#pragma once
/// @file atomic_file.hpp
/// @brief Write to "<path>.tmp-<pid>", rename onto <path> on commit(); remove the temporary
/// otherwise, also when SIGINT or SIGTERM ends the process mid-write (pending_temp_files.hpp).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "../util/error.hpp"
#include "pending_temp_files.hpp"

namespace lucent::io {

/// Throws InputError naming the file when it cannot be written because its folder is missing: front
/// ends call this for every output before any work, so nothing is written unless everything can be.
inline void checkWritable(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty() && !std::filesystem::is_directory(parent))
    throw InputError("cannot write '" + path + "': folder '" + parent.string() +
                     "' does not exist; create it first");
}

class AtomicFile {
 public:
  explicit AtomicFile(std::string path) : mPath(std::move(path)) {
    checkWritable(mPath);
    mTemp = mPath + ".tmp-" + std::to_string(::getpid());
    mSlot = PendingTempFiles::add(mTemp);
  }
  ~AtomicFile() {
    if (!mCommitted) {
      std::error_code ec;
      std::filesystem::remove(mTemp, ec);
    }
    PendingTempFiles::remove(
        mSlot);  // after the file is gone: a signal in between still removes it
  }
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& tempPath() const { return mTemp; }
  void commit() {
    std::error_code ec;
    std::filesystem::rename(mTemp, mPath, ec);
    if (ec)
      throw InputError("cannot write '" + mPath + "': " + ec.message() +
                       "; check free space and permissions, or choose another folder");
    mCommitted = true;
  }

 private:
  std::string mPath, mTemp;
  int mSlot = -1;
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
