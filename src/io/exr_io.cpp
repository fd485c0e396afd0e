#include "exr_io.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#include <cstdio>
#include <filesystem>
#include <vector>

#include "../util/error.hpp"
#include "atomic_file.hpp"

namespace lucent::io {

void writeExr(const std::string& path, const image::Image& img) {
  AtomicFile out(path);
  try {
    Imf::Header header(img.width, img.height);
    const char* names[4] = {"R", "G", "B", "A"};
    for (const char* n : names) header.channels().insert(n, Imf::Channel(Imf::FLOAT));
    Imf::OutputFile file(out.tempPath().c_str(), header);
    Imf::FrameBuffer fb;
    auto* base = reinterpret_cast<char*>(const_cast<glm::vec4*>(img.pixels.data()));
    for (int c = 0; c < 4; ++c)
      fb.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), sizeof(glm::vec4),
                                     sizeof(glm::vec4) * std::size_t(img.width)));
    file.setFrameBuffer(fb);
    file.writePixels(img.height);
  } catch (const std::exception& e) {
    throw InputError("cannot write '" + path + "': " + e.what() + "; check that the folder exists and is writable");
  }
  out.commit();
}

image::Image readExr(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError("cannot read '" + path + "': no such file; check the path");
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i dw = file.header().dataWindow();
    const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
    image::Image img(w, h);
    const bool hasAlpha = file.header().channels().findChannel("A") != nullptr;
    if (!file.header().channels().findChannel("R"))
      throw InputError("'" + path + "' has no R channel: lucent reads RGB(A) EXR images; convert it to RGB");
    Imf::FrameBuffer fb;
    auto* base = reinterpret_cast<char*>(img.pixels.data()) -
                 (std::ptrdiff_t(dw.min.x) + std::ptrdiff_t(dw.min.y) * w) * std::ptrdiff_t(sizeof(glm::vec4));
    const char* names[4] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c)
      fb.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), sizeof(glm::vec4),
                                     sizeof(glm::vec4) * std::size_t(w), 1, 1, c == 3 ? 1.0 : 0.0));
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
    if (!hasAlpha)
      for (auto& p : img.pixels) p.a = (p.r != 0 || p.g != 0 || p.b != 0) ? 1.0f : 0.0f;
    return img;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError("cannot read '" + path + "' as OpenEXR: " + e.what() + "; is it an .exr file?");
  }
}

}  // namespace lucent::io
