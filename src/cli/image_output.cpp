#include "image_output.hpp"

#include <cmath>
#include <stdexcept>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "../io/exr_io.hpp"
#include "../io/png_io.hpp"
#include "../util/error.hpp"

namespace lucent::cli {

namespace {
std::string extensionOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}
}  // namespace

bool isExr(const std::string& path) { return extensionOf(path) == ".exr"; }
bool isPng(const std::string& path) { return extensionOf(path) == ".png"; }

std::vector<OptionSpec> toneMapOptionSpecs() {
  return {{"tonemap", "paper|exposure",
           "PNG tone mapping: the paper's s/(1+s), s = key L/L_avg (default), or exposure + sRGB"},
          {"key", "X", "paper tone map: key (default 1)"},
          {"exposure", "STOPS", "exposure tone map: stops (default 0)"}};
}

image::ToneMap toneMapFromArgs(const Args& args) {
  image::ToneMap t;
  const std::string kind = args.get("tonemap", "paper");
  if (kind == "exposure")
    t.kind = image::ToneMap::Kind::Exposure;
  else if (kind != "paper")
    args.fail("--tonemap must be 'paper' or 'exposure', not '" + kind + "'");
  t.key = args.number("key", 1.0, 1e-6, 1e6);
  t.exposureStops = args.number("exposure", 0.0, -50, 50);
  return t;
}

void writeImage(const std::string& path, const image::Image& linear,
                const image::ToneMap& toneMap) {
  // Input is checked so that no technique produces one; should one appear anyway, nothing is
  // written.
  for (std::size_t i = 0; i < linear.pixels.size(); ++i)
    for (int c = 0; c < 4; ++c)
      if (!std::isfinite(linear.pixels[i][c]))
        throw std::runtime_error("pixel (" + std::to_string(i % std::size_t(linear.width)) + ", " +
                                 std::to_string(i / std::size_t(linear.width)) +
                                 ") is not finite; nothing was written to '" + path +
                                 "' (please report this)");
  const std::string ext = extensionOf(path);
  if (ext == ".exr")
    io::writeExr(path, linear);
  else if (ext == ".png")
    io::writePng(path, toneMap.map(linear));
  else
    throw InputError("cannot write '" + path + "': unknown image extension '" + ext +
                     "'; use .exr (linear) or .png");
}

image::Image readImage(const std::string& path) {
  const std::string ext = extensionOf(path);
  if (ext == ".exr") return io::readExr(path);
  if (ext == ".png") return io::readPng(path);
  throw InputError("cannot read '" + path + "': unknown image extension '" + ext +
                   "'; use .exr or .png");
}

}  // namespace lucent::cli
