#include <doctest/doctest.h>

#include <cmath>

#include <lucent/image/metrics.hpp>

using namespace lucent::image;

TEST_CASE("The paper's tone map: s/(1+s), the average maps to 1/2, monotone, NaN-safe") {
  ToneMap t;
  CHECK(t.apply(2.0f, 2.0) == doctest::Approx(0.5));
  CHECK(t.apply(0.0f, 2.0) == 0.0f);
  CHECK(t.apply(1e30f, 2.0) <= 1.0f);
  CHECK(t.apply(std::nanf(""), 2.0) == 0.0f);
  CHECK(t.apply(1.0f, 0.0) == 0.0f);  // an empty image has no average: black, not NaN
  float previous = 0;
  for (float l = 0.01f; l < 100; l *= 1.5f) {
    CHECK(t.apply(l, 1.0) > previous);
    previous = t.apply(l, 1.0);
  }
}

TEST_CASE("Image errors: zero for identical images, exact for a known difference") {
  Image a(4, 2), b(4, 2);
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    a.pixels[i] = b.pixels[i] = glm::vec4(1, 2, 3, 1);
  ImageErrors same = compareImages(a, b);
  CHECK(same.rmseToneMapped == 0);
  CHECK(same.relativeRms == 0);
  CHECK(same.coveredPixels == 8);
  a.pixels[0] = glm::vec4(2, 2, 3, 1);  // one channel of one pixel off by 1
  const ImageErrors e = compareImages(a, b);
  CHECK(e.maxAbsError == doctest::Approx(1.0));
  CHECK(e.relativeRms == doctest::Approx(std::sqrt(1.0 / (8 * 14.0))));
  b.pixels[1].a = 0;  // coverage differs in one pixel
  CHECK(compareImages(a, b).coverageMismatch == 1);
  CHECK_THROWS_AS(compareImages(Image(3, 3), Image(3, 4)), std::invalid_argument);
}

TEST_CASE("The scaled error removes a per-channel factor and keeps the error of the shape") {
  Image a(2, 1), b(2, 1);
  b.pixels = {glm::vec4(1, 2, 4, 1), glm::vec4(3, 1, 2, 1)};
  a.pixels = {glm::vec4(2, 6, 0.4f, 1), glm::vec4(6, 3, 0.2f, 1)};  // 2x, 3x, 0.1x of b
  const ImageErrors scaled = compareImages(a, b);
  CHECK(scaled.relativeRms > 0.5);
  CHECK(scaled.scaledRelativeRms < 1e-7);
  CHECK(compareImages(b, b).scaledRelativeRms == 0);
  // One channel's shape differs: a = (1, 0) against b = (0, 1) is orthogonal, nothing scales it
  // closer than 0, leaving that channel's whole energy (1 of the total 1 + 1).
  Image c(2, 1), d(2, 1);
  d.pixels = {glm::vec4(0, 1, 0, 1), glm::vec4(1, 0, 0, 1)};
  c.pixels = {glm::vec4(1, 1, 0, 1), glm::vec4(0, 0, 0, 1)};
  CHECK(compareImages(c, d).scaledRelativeRms == doctest::Approx(std::sqrt(0.5)));
}
