#pragma once
/// @file specular.hpp
/// @brief The specular component of Wang, Tran, Luebke 2005 (Sec. 4: "a pre-convolved environment
/// map to add a specular component"): the smooth boundary's Fresnel reflectance times the
/// environment, turned as the frame asks, seen in the mirror direction through a normalised Phong
/// lobe. As in the paper it is an environment-map lookup: self-shadowing is ignored (the
/// translucent part carries it).
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "../optics/fresnel.hpp"
#include "../scene/environment_resample.hpp"
#include "../util/parallel.hpp"

namespace lucent::prt {

class SpecularEnvironment {
 public:
  /// `envs` turned by `angle` radians about +y. `exponent` 0: a mirror, each environment read at
  /// its own resolution; else the lobe cos^exponent about the mirror direction, pre-convolved on
  /// `cube`, the environments summed on a cube `size` across and turned (scene::sumOnCube; a frame
  /// has it already), normalised over the texels it covers: a uniform environment stays uniform.
  /// The convolution costs (6 size^2)^2 multiply-adds.
  SpecularEnvironment(std::vector<const scene::EnvironmentLight*> envs,
                      const std::vector<glm::vec3>& cube, int size, double angle, double exponent,
                      const util::ParallelFor& parallelFor)
      : mEnvs(std::move(envs)), mAngle(angle), mSize(size) {
    if (exponent > 0) convolve(cube, exponent, parallelFor);
  }

  /// Radiance reflected towards `toEye` by a smooth boundary of relative index `eta` with
  /// `normal`: Fr(eta, cos) L_lobe(mirror direction).
  glm::dvec3 radiance(const glm::dvec3& normal, const glm::dvec3& toEye, double eta) const {
    const double c = glm::dot(normal, toEye);
    if (!(c > 0)) return glm::dvec3(0);
    return optics::fresnelReflectance(c, eta) * lookup(2 * c * normal - toEye);
  }

 private:
  glm::dvec3 lookup(const glm::dvec3& direction) const {
    if (!mConvolved.empty()) return mConvolved[scene::cube::texelIndex(direction, mSize)];
    glm::dvec3 sum(0);
    const glm::dvec3 source = mAngle == 0 ? direction : scene::turnAboutY(direction, -mAngle);
    for (const scene::EnvironmentLight* env : mEnvs) sum += env->lookup(source);
    return sum;
  }

  /// L_lobe(r) = sum_k L_k Omega_k max(0, r.w_k)^n / sum_k Omega_k max(0, r.w_k)^n.
  void convolve(const std::vector<glm::vec3>& cube, double exponent,
                const util::ParallelFor& parallelFor) {
    const std::size_t texels = cube.size();
    std::vector<glm::dvec3> direction(texels);
    std::vector<double> solidAngle(texels);
    for (std::size_t k = 0; k < texels; ++k) {
      direction[k] = scene::cube::texelCentre(k, mSize);
      solidAngle[k] = scene::cube::texelSolidAngle(int(k / mSize % mSize), int(k % mSize), mSize);
    }
    mConvolved.assign(texels, glm::dvec3(0));
    parallelFor(texels, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        glm::dvec3 sum(0);
        double weight = 0;
        for (std::size_t k = 0; k < texels; ++k) {
          const double c = glm::dot(direction[i], direction[k]);
          if (c <= 0) continue;
          const double w = solidAngle[k] * std::pow(c, exponent);
          sum += w * glm::dvec3(cube[k]), weight += w;
        }
        mConvolved[i] = sum / weight;  // weight > 0: the texel's own direction is in its lobe
      }
    });
  }

  std::vector<const scene::EnvironmentLight*> mEnvs;
  double mAngle = 0;
  int mSize = 0;
  std::vector<glm::dvec3> mConvolved;  ///< the pre-convolved cube (empty for the mirror)
};

}  // namespace lucent::prt
