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
  for (std::size_t i = 0; i < a.pixels.size(); ++i) a.pixels[i] = b.pixels[i] = glm::vec4(1, 2, 3, 1);
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
