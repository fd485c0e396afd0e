#include "report_cache.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "../io/atomic_file.hpp"
#include "../io/exr_io.hpp"
#include "../util/error.hpp"

namespace lucent::report {

void addFile(util::Fingerprint& f, const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read '" + path + "' to fingerprint it; check its permissions");
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
    f.addBytes(buffer, std::size_t(in.gcount()));
  f.addBytes("", 1);
}

ResultCache::ResultCache(std::string folder, std::string sceneKey)
    : mFolder(std::move(folder)), mSceneKey(std::move(sceneKey)) {
  std::error_code ec;
  std::filesystem::create_directories(mFolder, ec);
  if (ec || !std::filesystem::is_directory(mFolder))
    throw InputError("cannot create the cache folder '" + mFolder + "': " + ec.message() +
                     "; choose an --out folder you can write to");
}

std::string ResultCache::stem(const std::string& technique, const std::string& knobs) const {
  return technique + "-" + util::Fingerprint().add(mSceneKey).add(technique).add(knobs).hex();
}

namespace {
/// One "name<TAB>value" per line; the values hold no newline (knob summaries, numbers, warnings).
std::string fieldsText(const SettingResult& r) {
  std::ostringstream o;
  o.precision(17);
  o << "technique\t" << r.technique << "\nknobs\t" << r.knobs << "\nchanged\t" << r.changedKnobs
    << "\nseconds\t" << r.seconds << "\nprepare\t" << r.prepareSeconds << "\nframe\t"
    << r.frameSeconds << "\nsamples\t" << r.samples << "\nunit\t" << r.sampleUnit << "\nbytes\t"
    << r.bytes << "\n";
  for (std::string w : r.warnings) {
    for (char& c : w)
      if (c == '\n' || c == '\t') c = ' ';
    o << "warning\t" << w << "\n";
  }
  o << "complete\t1\n";  // last: a file cut short lacks it
  return o.str();
}

double numberField(const std::multimap<std::string, std::string>& f, const char* name) {
  const auto it = f.find(name);
  return it == f.end() ? std::nan("") : std::strtod(it->second.c_str(), nullptr);
}
}  // namespace

std::optional<SettingResult> ResultCache::load(const std::string& technique,
                                               const std::string& knobs, int width,
                                               int height) const {
  const std::string base = mFolder + "/" + stem(technique, knobs);
  std::ifstream in(base + ".txt");
  if (!in || !std::filesystem::exists(base + ".exr")) return std::nullopt;
  std::multimap<std::string, std::string> f;
  for (std::string line; std::getline(in, line);) {
    const auto tab = line.find('\t');
    if (tab != std::string::npos) f.emplace(line.substr(0, tab), line.substr(tab + 1));
  }
  auto text = [&](const char* name) {
    const auto it = f.find(name);
    return it == f.end() ? std::string() : it->second;
  };
  // A different setting under the same stem (a hash collision) or a partial file: measure again.
  if (text("complete") != "1" || text("technique") != technique || text("knobs") != knobs)
    return std::nullopt;
  SettingResult r;
  r.technique = technique, r.knobs = knobs, r.changedKnobs = text("changed");
  r.seconds = numberField(f, "seconds"), r.prepareSeconds = numberField(f, "prepare");
  r.frameSeconds = numberField(f, "frame"), r.samples = numberField(f, "samples");
  r.sampleUnit = text("unit"), r.bytes = numberField(f, "bytes");
  for (auto [it, end] = f.equal_range("warning"); it != end; ++it) r.warnings.push_back(it->second);
  if (!std::isfinite(r.seconds) || !(r.seconds >= 0)) return std::nullopt;
  try {
    r.image = io::readExr(base + ".exr");
  } catch (const std::exception&) {
    return std::nullopt;  // unreadable: measure again
  }
  // Replaced, resized or damaged since it was stored: measure again.
  if (r.image.width != width || r.image.height != height) return std::nullopt;
  for (const auto& p : r.image.pixels)
    if (!(std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b) && std::isfinite(p.a)))
      return std::nullopt;
  return r;
}

void ResultCache::store(const SettingResult& r) const {
  const std::string base = mFolder + "/" + stem(r.technique, r.knobs);
  io::writeExr(base + ".exr", r.image);  // the image first: the text file marks the result whole
  io::writeTextFile(base + ".txt", fieldsText(r));
}

}  // namespace lucent::report
