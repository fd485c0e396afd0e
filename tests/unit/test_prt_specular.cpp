// The PRT's specular component (prt/specular.hpp) against closed forms: a uniform environment
// reflects Fr(eta, cos) L, mirror or lobe; one bright texel is seen only in its mirror direction,
// turned with the environment.
#include <doctest/doctest.h>

#include <cmath>

#include <lucent/optics/fresnel.hpp>
#include <lucent/prt/specular.hpp>

using namespace lucent;

namespace {
scene::EnvironmentLight latLong(int width, int height, glm::vec3 radiance) {
  scene::EnvironmentLight env;
  env.width = width, env.height = height;
  env.radiance.assign(std::size_t(width) * height, radiance);
  return env;
}
}  // namespace

TEST_CASE("PRT specular: a uniform environment reflects Fr(eta, cos) L, mirror or lobe") {
  const scene::EnvironmentLight sky = latLong(16, 8, glm::vec3(2.0f));
  const double eta = 1.4;
  for (const double lobe : {0.0, 20.0, 400.0}) {
    const prt::SpecularEnvironment specular({&sky}, scene::sumOnCube({&sky}, 8, 0.3), 8, 0.3, lobe,
                                            util::serialFor);
    for (const glm::dvec3 n : {glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(1, -2, 0.5))}) {
      glm::dvec3 t = glm::normalize(glm::cross(n, glm::dvec3(0.3, 0.1, 0.9)));
      for (const double angle : {0.0, 1.0, 1.5}) {  // radians from the normal
        const glm::dvec3 toEye = std::cos(angle) * n + std::sin(angle) * t;
        const glm::dvec3 l = specular.radiance(n, toEye, eta);
        INFO("lobe " << lobe << ", angle " << angle);
        // The mirror reads the environment itself; a lobe reads the cube it was resampled onto,
        // uniform to the resampling's texel accuracy (0.3 % here).
        CHECK(l.y == doctest::Approx(2 * optics::fresnelReflectance(std::cos(angle), eta))
                         .epsilon(lobe == 0 ? 1e-12 : 0.01));
      }
      CHECK(specular.radiance(n, -n, eta) == glm::dvec3(0));  // seen from inside: none
    }
  }
}

TEST_CASE("PRT specular mirror: one bright texel is seen only in its mirror direction, turned") {
  scene::EnvironmentLight sky = latLong(32, 16, glm::vec3(0.0f));
  const std::size_t bright = 5 * 32 + 11;
  sky.radiance[bright] = glm::vec3(1000.0f);
  // The texel's centre direction, found by the environment's own mapping.
  glm::dvec3 toTexel(0);
  for (int i = 0; i < 20000 && toTexel == glm::dvec3(0); ++i) {
    const double z = 1 - 2 * (i + 0.5) / 20000, phi = 2.39996 * i;
    const glm::dvec3 d(std::sqrt(1 - z * z) * std::cos(phi), z,
                       std::sqrt(1 - z * z) * std::sin(phi));
    if (sky.texelOf(d) == bright) toTexel = d;
  }
  REQUIRE(toTexel != glm::dvec3(0));
  const double angle = 0.7;
  const prt::SpecularEnvironment specular({&sky}, scene::sumOnCube({&sky}, 8, angle), 8, angle, 0,
                                          util::serialFor);
  const glm::dvec3 turned = scene::turnAboutY(toTexel, angle);
  // Head-on at the normal facing the turned texel: the mirror direction is the normal itself.
  CHECK(specular.radiance(turned, turned, 1.3).x ==
        doctest::Approx(1000 * optics::fresnelReflectance(1.0, 1.3)));
  CHECK(specular.radiance(toTexel, toTexel, 1.3).x == 0);  // where it was before the turn
}
