#pragma once
/// @file png_io.hpp
/// @brief 8-bit PNG of display values in [0,1] (already tone-mapped), with VTK's PNG writer and reader.
#include <string>

#include <lucent/image/image.hpp>

namespace lucent::io {

/// Writes RGB of `display` (clamped to [0,1]) as 8-bit; atomically (temporary file, then rename).
void writePng(const std::string& path, const image::Image& display);
/// Reads display values in [0,1]; A = 1 for every pixel (a PNG carries no coverage lucent trusts).
image::Image readPng(const std::string& path);

}  // namespace lucent::io
