#pragma once
/// @file environment_sampling.hpp
/// @brief Importance sampling of an environment: a texel is drawn with probability proportional to
/// its luminance times its solid angle, then a direction within the texel: for a lat-long texel
/// uniform in phi and in cos theta (uniform in solid angle); for a cube-map texel uniform on the
/// face, whose solid-angle density is (1 + s^2 + t^2)^{3/2} / area. The pdf is exact, so estimators
/// stay unbiased.
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "cube_map.hpp"
#include "light.hpp"

namespace lucent::scene {

class EnvironmentSampler {
 public:
  explicit EnvironmentSampler(const EnvironmentLight& env) : mEnv(&env) {
    const std::size_t n = env.texelCount();
    mCdf.assign(n + 1, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      const glm::dvec3 l = glm::dvec3(env.radiance[i]) * env.scale;
      const double weight = std::max(0.0, (l.x + l.y + l.z) / 3) * env.texelSolidAngle(i);
      mCdf[i + 1] = mCdf[i] + weight;
    }
    mTotal = mCdf.back();
  }
  /// False for a black map (nothing to sample).
  bool valid() const { return mTotal > 0; }

  /// A direction towards the environment and its pdf in solid angle.
  glm::dvec3 sample(double u0, double u1, double u2, double& pdf) const {
    const double target = u0 * mTotal;
    const std::size_t i = std::min<std::size_t>(
        mCdf.size() - 2,
        std::size_t(std::upper_bound(mCdf.begin(), mCdf.end(), target) - mCdf.begin()) - 1);
    const double texelProbability = (mCdf[i + 1] - mCdf[i]) / mTotal;
    const int width = mEnv->width;
    const int row = int(i / std::size_t(width)), col = int(i % std::size_t(width));
    if (mEnv->layout == EnvironmentLayout::Cube) {
      const double s = cube::edgeCoordinate(col, width) + 2.0 * u2 / width;
      const double t = cube::edgeCoordinate(row % width, width) + 2.0 * u1 / width;
      const double area = 4.0 / (double(width) * width);
      pdf = texelProbability / area * std::pow(1 + s * s + t * t, 1.5);
      return glm::normalize(cube::faceDirection(row / width, s, t));
    }
    const double cos0 = std::cos(optics::kPi * row / mEnv->height);
    const double cos1 = std::cos(optics::kPi * (row + 1) / mEnv->height);
    const double cosTheta = cos0 + u1 * (cos1 - cos0);
    const double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
    const double phi = 2 * optics::kPi * (col + u2) / width;
    pdf = texelProbability / mEnv->texelSolidAngle(i);
    // The layout of EnvironmentLight::lookup: theta from +y, phi = atan2(x, -z).
    return {sinTheta * std::sin(phi), cosTheta, -sinTheta * std::cos(phi)};
  }

  /// The solid-angle pdf with which sample() draws `dir` (any length but zero): what multiple
  /// importance sampling weighs a direction drawn another way with.
  double pdf(const glm::dvec3& dir) const {
    if (!valid()) return 0;
    const std::size_t i = mEnv->texelOf(dir);
    const double texelProbability = (mCdf[i + 1] - mCdf[i]) / mTotal;
    if (mEnv->layout == EnvironmentLayout::Cube) {
      const cube::FacePoint f = cube::facePoint(dir);
      const double area = 4.0 / (double(mEnv->width) * mEnv->width);
      return texelProbability / area * std::pow(1 + f.s * f.s + f.t * f.t, 1.5);
    }
    return texelProbability / mEnv->texelSolidAngle(i);
  }

 private:
  const EnvironmentLight* mEnv;
  std::vector<double> mCdf;
  double mTotal = 0;
};

}  // namespace lucent::scene
