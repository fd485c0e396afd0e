#pragma once
/// @file image_output.hpp
/// @brief Writes a rendered image by extension: .exr (linear radiance + coverage) or .png (tone-mapped).
#include <string>

#include <lucent/image/tonemap.hpp>

#include "args.hpp"

namespace lucent::cli {

/// Tone-mapping options shared by render and compare.
std::vector<OptionSpec> toneMapOptionSpecs();
image::ToneMap toneMapFromArgs(const Args& args);
/// Throws InputError for an extension other than .exr / .png.
void writeImage(const std::string& path, const image::Image& linear, const image::ToneMap& toneMap);
/// Reads .exr (linear) or .png (display values).
image::Image readImage(const std::string& path);
bool isExr(const std::string& path);
bool isPng(const std::string& path);

}  // namespace lucent::cli
