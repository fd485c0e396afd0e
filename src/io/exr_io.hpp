#pragma once
/// @file exr_io.hpp
/// @brief Linear HDR images as OpenEXR (32-bit float RGBA). Writes go to a temporary file that is renamed
/// into place, so a failed or interrupted write never leaves a half-written image.
#include <string>

#include <lucent/image/image.hpp>

namespace lucent::io {

void writeExr(const std::string& path, const image::Image& img);
/// Reads R, G, B (and A if present; otherwise A = 1 where any channel is non-zero). Throws InputError.
image::Image readExr(const std::string& path);

}  // namespace lucent::io
