#pragma once
// Chandrasekhar's H-function for isotropic scattering, solved numerically: the independent
// reference of the Monte Carlo tests (pencil beam and volume path tracer).
#include <cmath>
#include <vector>

#include <glm/vec3.hpp>

#include <lucent/optics/constants.hpp>
#include <lucent/scene/camera.hpp>
#include <lucent/util/rng.hpp>

namespace lucent::test {
// Gauss-Legendre nodes and weights on [0, 1] (Newton on P_n), for the H-function quadrature.
inline void gaussLegendre01(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(std::size_t(n), 0);
  w.assign(std::size_t(n), 0);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(optics::kPi * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1, p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-15) break;
    }
    x[std::size_t(i)] = 0.5 * (1 - z);
    w[std::size_t(i)] = 1.0 / ((1 - z * z) * dp * dp);  // 2/((1-z^2) P'^2), halved for [0,1]
  }
}

// Chandrasekhar's H-function for isotropic scattering with single-scattering albedo a, by
// fixed-point iteration of 1/H(mu) = sqrt(1-a) + (a/2) int_0^1 mu' H(mu') / (mu + mu') dmu'
// (Chandrasekhar 1960, Radiative Transfer, the form that converges for every a < 1).
inline double chandrasekharH(double mu, double a) {
  std::vector<double> x, w;
  gaussLegendre01(48, x, w);
  std::vector<double> h(x.size(), 1.0);
  auto evaluate = [&](double m) {
    double s = 0;
    for (std::size_t j = 0; j < x.size(); ++j) s += w[j] * x[j] * h[j] / (m + x[j]);
    return 1.0 / (std::sqrt(1 - a) + 0.5 * a * s);
  };
  for (int it = 0; it < 2000; ++it) {
    std::vector<double> next(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) next[i] = evaluate(x[i]);
    h.swap(next);
  }
  return evaluate(mu);
}

// Radiance reflected towards mu by an isotropically scattering half-space of albedo a under a
// normally incident beam of unit irradiance: (a / 4pi) H(mu) H(1) / (1 + mu) (Chandrasekhar 1960).
inline double halfSpaceReflected(double mu, double a) {
  return a / (4 * optics::kPi) / (1 + mu) * chandrasekharH(mu, a) * chandrasekharH(1.0, a);
}

// Three channels' albedos, rays towards the eye at mu aimed at the half-space's face z = 0, and
// each channel's reflected radiance.
struct HalfSpaceView {
  glm::dvec3 toEye, exact;
  scene::Ray rayAt(util::Rng& rng) const {
    const glm::dvec3 target(4 * rng.uniform() - 2, 4 * rng.uniform() - 2, 0);
    return scene::Ray{target + 50.0 * toEye, -toEye};
  }
};
inline HalfSpaceView halfSpaceView(double mu, const glm::dvec3& albedo) {
  HalfSpaceView v{glm::dvec3(std::sqrt(1 - mu * mu), 0, mu), glm::dvec3(0)};
  for (int c = 0; c < 3; ++c) v.exact[c] = halfSpaceReflected(mu, albedo[c]);
  return v;
}
}  // namespace lucent::test
