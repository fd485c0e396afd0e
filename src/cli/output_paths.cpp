#include "output_paths.hpp"

#include <unistd.h>

#include <filesystem>
#include <set>

#include "../util/error.hpp"

namespace lucent::cli {

namespace fs = std::filesystem;

namespace {
/// One file however it is spelled (relative, "./", a link): its canonical path when it exists,
/// else its folder's canonical path and its name.
std::string identity(const std::string& path) {
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? path : canonical.string();
}

/// Whether `a` and `b` are one file: one path however spelled, or hard links to one inode.
bool sameFile(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (identity(a) == identity(b)) return true;
  return fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec);
}

/// The existing regular files an option's value names, whole or in parts.
std::vector<std::string> filesNamedBy(const std::string& value) {
  std::vector<std::string> parts{value};
  std::string part;
  for (char c : value + ':') {
    if (c == ':' || c == ',' || c == '=') {
      if (!part.empty() && part != value) parts.push_back(part);
      part.clear();
    } else {
      part += c;
    }
  }
  std::vector<std::string> files;
  std::error_code ec;
  for (const std::string& p : parts)
    if (fs::is_regular_file(p, ec)) files.push_back(p);
  return files;
}

void checkOne(const std::string& command, const NamedOutput& o) {
  const std::string what = "lucent " + command + ": " + o.option + " " + o.path + ": ";
  std::error_code ec;
  if (fs::is_directory(o.path, ec)) throw InputError(what + "is a folder; give a file name in it");
  const fs::path parent = fs::path(o.path).parent_path();
  const std::string folder = parent.empty() ? "." : parent.string();
  if (!fs::is_directory(folder, ec))
    throw InputError(what + "its folder '" + folder + "' does not exist; create it first");
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw InputError(what + "its folder '" + folder +
                     "' does not take new files (permissions); choose a writable folder");
  if (fs::exists(o.path, ec) && ::access(o.path.c_str(), W_OK) != 0)
    throw InputError(what + "the file exists and is read-only; choose another name");
}
}  // namespace

void checkOutputs(const Args& args, const std::vector<NamedOutput>& outputs,
                  const std::vector<NamedOutput>& hidden) {
  const std::string prefix = "lucent " + args.command() + ": ";
  std::set<std::string> outputOptions;  // "out", "stats", "knob": what they name is written
  for (const NamedOutput& o : outputs)
    outputOptions.insert(o.option.substr(2, o.option.find(' ') - 2));
  for (const auto& [name, values] : args.given()) {
    if (outputOptions.count(name)) continue;
    for (const std::string& value : values)
      for (const std::string& file : filesNamedBy(value))
        for (const NamedOutput& o : outputs)
          if (sameFile(o.path, file))
            throw InputError(prefix + o.option + " " + o.path + " is the input --" + name + " " +
                             value + "; writing it would replace the input: give another name");
  }
  for (const NamedOutput& input : hidden)
    for (const NamedOutput& o : outputs)
      if (sameFile(o.path, input.path))
        throw InputError(prefix + o.option + " " + o.path + " is read by " + input.option +
                         "; writing it would replace the input: give another name");
  std::set<std::string> seen;
  for (const NamedOutput& o : outputs) {
    checkOne(args.command(), o);
    if (!seen.insert(identity(o.path)).second)
      throw InputError(prefix + o.option + " " + o.path +
                       " is also another output of this command; give each output its own name");
  }
}

}  // namespace lucent::cli
