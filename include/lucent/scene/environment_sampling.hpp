#pragma once
/// @file environment_sampling.hpp
/// @brief Importance sampling of a lat-long environment: a pixel is drawn with probability proportional
/// to its luminance times its solid angle, then a direction uniformly within the pixel (uniform in phi
/// and in cos theta, which is uniform in solid angle). The pdf is exact, so estimators stay unbiased.
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/vec3.hpp>

#include "light.hpp"

namespace lucent::scene {

class EnvironmentSampler {
 public:
  explicit EnvironmentSampler(const EnvironmentLight& env) : mEnv(&env) {
    const std::size_t n = std::size_t(env.width) * std::size_t(env.height);
    mCdf.assign(n + 1, 0.0);
    for (int row = 0; row < env.height; ++row)
      for (int col = 0; col < env.width; ++col) {
        const std::size_t i = std::size_t(row) * env.width + col;
        const glm::dvec3 l = glm::dvec3(env.radiance[i]) * env.scale;
        const double weight = std::max(0.0, (l.x + l.y + l.z) / 3) * pixelSolidAngle(row);
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
        mCdf.size() - 2, std::size_t(std::upper_bound(mCdf.begin(), mCdf.end(), target) - mCdf.begin()) - 1);
    const int row = int(i / std::size_t(mEnv->width)), col = int(i % std::size_t(mEnv->width));
    const double cos0 = std::cos(optics::kPi * row / mEnv->height), cos1 = std::cos(optics::kPi * (row + 1) / mEnv->height);
    const double cosTheta = cos0 + u1 * (cos1 - cos0), sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
    const double phi = 2 * optics::kPi * (col + u2) / mEnv->width;
    pdf = (mCdf[i + 1] - mCdf[i]) / mTotal / pixelSolidAngle(row);
    // The layout of EnvironmentLight::lookup: theta from +y, phi = atan2(x, -z).
    return {sinTheta * std::sin(phi), cosTheta, -sinTheta * std::cos(phi)};
  }

 private:
  double pixelSolidAngle(int row) const {
    const double cos0 = std::cos(optics::kPi * row / mEnv->height), cos1 = std::cos(optics::kPi * (row + 1) / mEnv->height);
    return 2 * optics::kPi / mEnv->width * (cos0 - cos1);
  }
  const EnvironmentLight* mEnv;
  std::vector<double> mCdf;
  double mTotal = 0;
};

}  // namespace lucent::scene
