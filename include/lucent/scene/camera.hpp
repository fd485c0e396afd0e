#pragma once
/// @file camera.hpp
/// @brief A pinhole camera, and automatic framing of a bounding sphere.
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "../optics/constants.hpp"
#include "mesh.hpp"

namespace lucent::scene {

struct Ray {
  glm::dvec3 origin;
  glm::dvec3 direction;  ///< unit length
};

struct PinholeCamera {
  glm::dvec3 eye{0, 0, 10};
  glm::dvec3 target{0, 0, 0};
  glm::dvec3 up{0, 1, 0};
  double verticalFovDeg = 30;
  int width = 512;
  int height = 512;

  /// Ray through the centre of pixel (px, py); row 0 is the top of the image.
  Ray primaryRay(double px, double py) const {
    const glm::dvec3 forward = glm::normalize(target - eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, up));
    const glm::dvec3 trueUp = glm::cross(right, forward);
    const double tanHalf = std::tan(0.5 * verticalFovDeg * optics::kPi / 180.0);
    const double aspect = double(width) / double(height);
    const double sx = (2.0 * (px + 0.5) / width - 1.0) * tanHalf * aspect;
    const double sy = (1.0 - 2.0 * (py + 0.5) / height) * tanHalf;
    return {eye, glm::normalize(forward + sx * right + sy * trueUp)};
  }

  /// Places the camera on `viewDirection` (from the target towards the eye) so that the bounding sphere
  /// of `bounds` fills `fill` of the smaller field of view.
  static PinholeCamera frame(const Bounds& bounds, glm::dvec3 viewDirection, int width, int height,
                             double verticalFovDeg = 30, double fill = 0.9) {
    PinholeCamera cam;
    cam.width = width;
    cam.height = height;
    cam.verticalFovDeg = verticalFovDeg;
    cam.target = bounds.center();
    const double radius = 0.5 * bounds.diagonal();
    const double halfFov = 0.5 * verticalFovDeg * optics::kPi / 180.0;
    const double aspect = double(width) / double(height);
    const double halfFovMin = aspect < 1 ? std::atan(std::tan(halfFov) * aspect) : halfFov;
    const double distance = radius / (std::sin(halfFovMin) * fill);
    cam.eye = cam.target + glm::normalize(viewDirection) * distance;
    if (std::abs(glm::dot(glm::normalize(viewDirection), cam.up)) > 0.999) cam.up = glm::dvec3(0, 0, 1);
    return cam;
  }
};

}  // namespace lucent::scene
