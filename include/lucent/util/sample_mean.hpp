#pragma once
/// @file sample_mean.hpp
/// @brief The running mean of a Monte Carlo estimator's samples, per channel, and the standard
/// error of that mean (the unbiased sample variance over n): what every progressive estimate
/// reports per pixel or point.
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/vec3.hpp>

namespace lucent::util {

struct SampleMean {
  glm::dvec3 sum{0}, sumSq{0};
  int n = 0;

  void add(const glm::dvec3& x) { sum += x, sumSq += x * x, ++n; }
  glm::dvec3 mean() const { return n ? sum / double(n) : glm::dvec3(0); }
  /// 0 below two samples (no spread to measure).
  glm::dvec3 standardError() const {
    if (n < 2) return glm::dvec3(0);
    const glm::dvec3 m = mean();
    const glm::dvec3 variance =
        glm::max(glm::dvec3(0), sumSq / double(n) - m * m) * (double(n) / (n - 1));
    return glm::sqrt(variance / double(n));
  }
};

}  // namespace lucent::util
