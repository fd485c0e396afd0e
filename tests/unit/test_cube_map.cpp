// Cube-map environments: texel solid angles, the face mapping, lat-long resampling that keeps the
// integral, image layouts whose faces meet at their edges, and an unbiased sampler.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include <lucent/optics/constants.hpp>
#include <lucent/scene/environment_resample.hpp>
#include <lucent/scene/environment_sampling.hpp>

namespace {
using namespace lucent::scene;

glm::dvec3 randomDirection(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return glm::normalize(glm::dvec3(n(rng), n(rng), n(rng)));
}

/// A lat-long probe of a smooth function of direction plus independent texel noise.
EnvironmentLight latLongProbe(int width, double noise, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  EnvironmentLight env;
  env.width = width, env.height = width / 2;
  for (int row = 0; row < env.height; ++row)
    for (int col = 0; col < env.width; ++col) {
      const double theta = lucent::optics::kPi * (row + 0.5) / env.height,
                   phi = 2 * lucent::optics::kPi * (col + 0.5) / env.width;
      const glm::dvec3 d(std::sin(theta) * std::sin(phi), std::cos(theta),
                         -std::sin(theta) * std::cos(phi));
      const double smooth = 1 + 0.5 * d.x + 0.25 * d.y * d.y;
      env.radiance.push_back(
          glm::vec3(float(smooth + noise * u(rng)), float(smooth), float(2 * smooth)));
    }
  return env;
}

glm::dvec3 integral(const EnvironmentLight& env) {
  glm::dvec3 sum(0);
  for (std::size_t i = 0; i < env.texelCount(); ++i)
    sum += glm::dvec3(env.radiance[i]) * env.texelSolidAngle(i);
  return sum * env.scale;
}

EnvironmentLight randomCube(int size, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.1f, 2.0f);
  EnvironmentLight env;
  env.layout = EnvironmentLayout::Cube;
  env.width = size, env.height = 6 * size;
  for (std::size_t i = 0; i < env.texelCount(); ++i)
    env.radiance.push_back({u(rng), u(rng), u(rng)});
  return env;
}
}  // namespace

TEST_CASE("Cube texels' exact solid angles are positive and sum to 4 pi") {
  for (int size : {1, 3, 16, 64}) {
    double sum = 0, smallest = 1e9, largest = 0;
    for (int row = 0; row < size; ++row)
      for (int col = 0; col < size; ++col) {
        const double w = cube::texelSolidAngle(row, col, size);
        sum += w, smallest = std::min(smallest, w), largest = std::max(largest, w);
      }
    CHECK(6 * sum == doctest::Approx(4 * lucent::optics::kPi).epsilon(1e-12));
    CHECK(smallest > 0);
    // Corner texels are smaller than centre ones by up to 3^{3/2} (the face's 1/(1+s^2+t^2)^{3/2}).
    CHECK(largest / smallest < 5.2 + 1e-9);
  }
}

TEST_CASE(
    "A direction's face point maps back to the direction, and a texel's centre to the texel") {
  std::mt19937 rng(7);
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 d = randomDirection(rng);
    const cube::FacePoint p = cube::facePoint(d);
    REQUIRE(p.face >= 0);
    REQUIRE(p.face < 6);
    CHECK(std::abs(p.s) <= 1 + 1e-12);
    CHECK(std::abs(p.t) <= 1 + 1e-12);
    const glm::dvec3 back = glm::normalize(cube::faceDirection(p.face, p.s, p.t));
    CHECK(glm::length(back - d) < 1e-12);
  }
  const int size = 5;
  for (std::size_t i = 0; i < std::size_t(6 * size * size); ++i)
    CHECK(cube::texelIndex(cube::texelCentre(i, size), size) == i);
  CHECK(cube::texelIndex(glm::dvec3(0), size) < std::size_t(6 * size * size));  // no crash on zero
}

TEST_CASE("Lat-long to cube keeps the integral to rounding and the radiance where it is smooth") {
  for (int width : {8, 64, 256}) {
    const EnvironmentLight probe = latLongProbe(width, 3.0, 11);
    const EnvironmentLight cubeMap = latLongToCube(probe, 16);
    REQUIRE(cubeMap.texelCount() == std::size_t(6 * 16 * 16));
    const glm::dvec3 a = integral(probe), b = integral(cubeMap);
    for (int c = 0; c < 3; ++c) CHECK(b[c] == doctest::Approx(a[c]).epsilon(1e-6));
  }
  // Channel 1 is the smooth function alone: the cube's texel equals its value at the centre to
  // within the splat's aliasing at texel edges (a few per cent) and the function's curvature.
  const EnvironmentLight cubeMap = latLongToCube(latLongProbe(512, 0, 3), 16);
  double worst = 0;
  for (std::size_t i = 0; i < cubeMap.texelCount(); ++i) {
    const glm::dvec3 d = cube::texelCentre(i, 16);
    const double expected = 1 + 0.5 * d.x + 0.25 * d.y * d.y;
    worst = std::max(worst, std::abs(cubeMap.radiance[i].y - expected) / expected);
  }
  CHECK(worst < 0.04);
  // And the lookup by direction reads the same texels.
  std::mt19937 rng(5);
  for (int i = 0; i < 200; ++i) {
    const glm::dvec3 d = randomDirection(rng);
    // ... and anywhere in the texel, to the function's change across half a texel as well.
    CHECK(cubeMap.lookup(d).y == doctest::Approx(1 + 0.5 * d.x + 0.25 * d.y * d.y).epsilon(0.08));
  }
}

TEST_CASE("Cube image layouts: every texel round-trips and the crosses' neighbouring faces meet") {
  const int size = 8;
  const EnvironmentLight env = randomCube(size, 1);
  for (auto layout : {cube::ImageLayout::HorizontalStrip, cube::ImageLayout::VerticalStrip,
                      cube::ImageLayout::HorizontalCross, cube::ImageLayout::VerticalCross}) {
    CAPTURE(cube::layoutName(layout));
    const int w = layout == cube::ImageLayout::HorizontalStrip   ? 6 * size
                  : layout == cube::ImageLayout::VerticalStrip   ? size
                  : layout == cube::ImageLayout::HorizontalCross ? 4 * size
                                                                 : 3 * size;
    const int h = layout == cube::ImageLayout::HorizontalStrip   ? size
                  : layout == cube::ImageLayout::VerticalStrip   ? 6 * size
                  : layout == cube::ImageLayout::HorizontalCross ? 3 * size
                                                                 : 4 * size;
    REQUIRE(cube::detectLayout(w, h) == layout);
    REQUIRE(cube::faceSize(layout, w, h) == size);
    // Write every texel into the image, remembering each pixel's direction.
    std::vector<glm::vec3> image(std::size_t(w) * h, glm::vec3(-1));
    std::vector<glm::dvec3> direction(image.size(), glm::dvec3(0));
    for (int face = 0; face < 6; ++face)
      for (int row = 0; row < size; ++row)
        for (int col = 0; col < size; ++col) {
          const auto xy = cube::imagePixel(layout, size, face, row, col);
          REQUIRE(xy[0] < w);
          REQUIRE(xy[1] < h);
          const std::size_t texel = (std::size_t(face) * size + row) * size + col;
          const std::size_t pixel = std::size_t(xy[1]) * w + xy[0];
          CHECK(image[pixel].x == -1.0f);  // no two texels on one pixel
          image[pixel] = env.radiance[texel];
          direction[pixel] = cube::texelCentre(texel, size);
        }
    const EnvironmentLight back =
        cubeFromImage(layout, size, [&](int x, int y) { return image[std::size_t(y) * w + x]; });
    CHECK(back.radiance == env.radiance);
    // In a cross, horizontally or vertically adjacent pixels of two faces look in nearly the same
    // direction (a texel apart), so the faces meet where the picture shows them meeting.
    if (layout == cube::ImageLayout::HorizontalCross ||
        layout == cube::ImageLayout::VerticalCross) {
      int seams = 0;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const glm::dvec3 d = direction[std::size_t(y) * w + x];
          if (glm::length(d) == 0) continue;
          for (auto [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
            if (x + dx >= w || y + dy >= h) continue;
            const glm::dvec3 e = direction[std::size_t(y + dy) * w + x + dx];
            if (glm::length(e) == 0) continue;
            CHECK(std::acos(std::min(1.0, glm::dot(d, e))) <
                  2.5 * (lucent::optics::kPi / 2) / size);
            seams += cube::facePoint(d).face != cube::facePoint(e).face;
          }
        }
      CHECK(seams == 5 * size);  // the five seams a cross shows
    }
  }
  CHECK_FALSE(cube::detectLayout(64, 32).has_value());  // lat-long
  CHECK_FALSE(cube::detectLayout(0, 0).has_value());
}

TEST_CASE("The cube-map sampler's pdf is exact: E[f/pdf] is the integral of f") {
  const EnvironmentLight env = randomCube(4, 9);
  const EnvironmentSampler sampler(env);
  REQUIRE(sampler.valid());
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  const int n = 400000;
  double sphere = 0, flux = 0, firstMoment = 0;
  for (int i = 0; i < n; ++i) {
    double pdf = 0;
    const glm::dvec3 d = sampler.sample(u(rng), u(rng), u(rng), pdf);
    REQUIRE(pdf > 0);
    CHECK(std::abs(glm::length(d) - 1) < 1e-12);
    sphere += 1 / pdf;
    flux += env.lookup(d).x / pdf;
    firstMoment += (1 + d.z) * env.lookup(d).y / pdf;
  }
  CHECK(sphere / n == doctest::Approx(4 * lucent::optics::kPi).epsilon(0.01));
  CHECK(flux / n == doctest::Approx(integral(env).x).epsilon(0.01));
  // The same moment by quadrature over each texel's sub-grid (independent of the sampler).
  double quadrature = 0;
  const int sub = 16;
  for (int face = 0; face < 6; ++face)
    for (int a = 0; a < 4 * sub; ++a)
      for (int b = 0; b < 4 * sub; ++b) {
        const double s = -1 + (b + 0.5) / (2.0 * sub), t = -1 + (a + 0.5) / (2.0 * sub);
        const glm::dvec3 d = glm::normalize(cube::faceDirection(face, s, t));
        const double dOmega =
            (1.0 / (2.0 * sub)) * (1.0 / (2.0 * sub)) / std::pow(1 + s * s + t * t, 1.5);
        quadrature += (1 + d.z) * env.lookup(d).y * dOmega;
      }
  CHECK(firstMoment / n == doctest::Approx(quadrature).epsilon(0.01));
}

TEST_CASE("The environment sampler's pdf(dir) is the density sample() drew dir with") {
  // Multiple importance sampling weighs a direction drawn another way by pdf(dir) (the random
  // walk's exits): it must agree with sample() for both layouts, and integrate to 1 over the
  // sphere.
  for (const EnvironmentLight& env : {latLongProbe(16, 3.0, 5), randomCube(4, 7)}) {
    const EnvironmentSampler sampler(env);
    REQUIRE(sampler.valid());
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 2000; ++i) {
      double pdf = 0;
      const glm::dvec3 d = sampler.sample(u(rng), u(rng), u(rng), pdf);
      CHECK(sampler.pdf(d) == doctest::Approx(pdf).epsilon(1e-9));
    }
    std::mt19937 dirs(13);
    double total = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) total += sampler.pdf(randomDirection(dirs));
    CHECK(total / n * 4 * lucent::optics::kPi == doctest::Approx(1).epsilon(0.02));
  }
}
