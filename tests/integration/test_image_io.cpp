#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include <limits>

#include "cli/image_output.hpp"
#include "io/exr_io.hpp"
#include "io/png_io.hpp"
#include "temp_dir.hpp"
#include "util/error.hpp"

using namespace lucent;

TEST_CASE("EXR round trip keeps float radiance and coverage exactly") {
  test::TempDir dir;
  image::Image img(7, 5);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 7; ++x)
      img.at(x, y) = glm::vec4(x * 0.125f, y * 1e-6f, 1e5f + x, (x + y) % 2);
  io::writeExr(dir / "a.exr", img);
  const image::Image back = io::readExr(dir / "a.exr");
  REQUIRE(back.width == 7);
  REQUIRE(back.height == 5);
  for (std::size_t i = 0; i < img.pixels.size(); ++i) CHECK(back.pixels[i] == img.pixels[i]);
}

TEST_CASE("PNG round trip of display values within one 8-bit step, rows in order") {
  test::TempDir dir;
  image::Image img(4, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) img.at(x, y) = glm::vec4(x / 3.0f, y / 2.0f, 0.5f, 1);
  io::writePng(dir / "a.png", img);
  const image::Image back = io::readPng(dir / "a.png");
  for (std::size_t i = 0; i < img.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      CHECK(std::abs(back.pixels[i][c] - img.pixels[i][c]) <= 0.5f / 255 + 1e-6f);
}

TEST_CASE("Image I/O errors name the file and the fix, and leave nothing half-written") {
  test::TempDir dir;
  const image::Image img(2, 2);
  try {
    io::writeExr(dir / "missing-folder/a.exr", img);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("does not exist") != std::string::npos);
  }
  { std::ofstream(dir / "not.exr") << "this is text"; }
  CHECK_THROWS_AS(io::readExr(dir / "not.exr"), InputError);
  CHECK_THROWS_AS(io::readExr(dir / "nothing.exr"), InputError);
  CHECK_THROWS_AS(io::readPng(dir / "not.exr"), InputError);
  for (const auto& entry : std::filesystem::directory_iterator(dir.path))
    CHECK(entry.path().filename().string().find(".tmp-") == std::string::npos);
}

TEST_CASE("An image with a non-finite pixel is never written") {
  lucent::test::TempDir dir;
  lucent::image::Image img(3, 2);
  img.pixels[4] = glm::vec4(std::numeric_limits<float>::infinity(), 0, 0, 1);
  for (const char* name : {"bad.exr", "bad.png"}) {
    CHECK_THROWS_WITH(lucent::cli::writeImage(dir / name, img, lucent::image::ToneMap{}),
                      doctest::Contains("pixel (1, 1) is not finite"));
    CHECK_FALSE(std::filesystem::exists(dir / name));
  }
}
