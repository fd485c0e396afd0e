#pragma once
// The hard-case matrix (issue 21): one technique on a sphere of one material, size and index of
// refraction, seen head-on under a sun behind the camera or a uniform environment. The outcome is
// either a refusal (the technique's stated range) or an image, summarised against the diffusion
// limit: where the object is many mean free paths across, the lit cap's radiosity is the local B =
// E_t Rd_total (Jensen et al. 2001's total diffuse reflectance), an analytic value independent of
// every technique.
#include <chrono>
#include <cmath>
#include <memory>
#include <string>

#include <lucent/optics/dipole.hpp>
#include <lucent/optics/fresnel.hpp>
#include <lucent/optics/materials.hpp>
#include <lucent/scene/camera.hpp>
#include <lucent/scene/shapes.hpp>
#include <lucent/technique/registry.hpp>

#include "raycast/embree_ray_caster.hpp"
#include "util/error.hpp"
#include "util/tbb_parallel.hpp"

namespace lucent::test {

struct HardCase {
  std::string material;
  double sizeMm = 30;  ///< bounding-box diagonal
  double eta = 1.3;
  bool environment = false;  ///< a uniform environment (radiance 1), else a head-on sun (E = 1)
};

/// E_t of the case's light at a point whose normal makes `cosine` with the view (= sun) direction:
/// Ft(cos) cos for the sun, 2 pi int_0^1 Ft(mu) mu dmu for the uniform environment.
inline double transmittedIrradiance(const HardCase& c, double cosine) {
  if (!c.environment) return optics::fresnelTransmittance(cosine, c.eta) * cosine;
  constexpr int n = 2000;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double mu = (i + 0.5) / n;
    sum += optics::fresnelTransmittance(mu, c.eta) * mu;
  }
  return 2 * optics::kPi * sum / n;
}

struct HardCaseOutcome {
  bool refused = false;
  std::string message;  ///< the refusal, or the technique's warnings
  bool finite = true, nonNegative = true;
  int litPixels = 0;    ///< pixels on the lit cap (normal within 37 degrees of the view)
  glm::dvec3 ratio{0};  ///< lit-cap radiance over the diffusion limit, per channel
  glm::dvec3 limit{0};  ///< the diffusion limit's mean radiance on the lit cap
  glm::dvec3 mean{0};   ///< the cap's mean radiance
  /// The standard error of `ratio` (Monte Carlo techniques, from their "stderr" output; else 0).
  glm::dvec3 ratioError{0};
  double seconds = 0;
};

inline HardCaseOutcome runHardCase(const technique::Registry& registry,
                                   const technique::Technique& t, const HardCase& c,
                                   const technique::KnobList& knobs) {
  namespace lt = technique;
  HardCaseOutcome out;
  lt::SceneDescription scene;
  const double radius = c.sizeMm / (2 * std::sqrt(3.0));  // the diagonal of the sphere's box
  scene.mesh = scene::shapes::sphere(radius, 2);
  scene.vertexNormals = scene.mesh.vertexNormals();
  scene.medium.material = *optics::findMaterial(c.material);
  scene.medium.material.eta = c.eta;
  const glm::dvec3 toLight(0, 0, 1);
  if (c.environment) {
    scene::EnvironmentLight env;
    env.width = env.height = 1;
    env.radiance = {glm::vec3(1.0f)};
    scene.lights = {env};
  } else {
    scene.lights = {scene::DirectionalLight{toLight, glm::dvec3(1)}};
  }
  raycast::EmbreeRayCaster caster(scene.mesh);
  scene.caster = &caster;
  scene.makeRayCaster = [](const scene::TriangleMesh& m) {
    return std::make_unique<raycast::EmbreeRayCaster>(m);
  };
  scene.parallelFor = util::tbbFor;
  const scene::PinholeCamera camera =
      scene::PinholeCamera::frame(scene.mesh.bounds(), toLight, 10, 10);
  const lt::ShadeRequest request = lt::pixelRequest(camera, scene);

  const auto start = std::chrono::steady_clock::now();
  lt::Rendered r;
  try {
    r = registry.render(t, scene, t.values(knobs), request);
  } catch (const technique::RequestError& e) {
    out.refused = true, out.message = e.what();
    return out;
  } catch (const InputError& e) {
    out.refused = true, out.message = e.what();
    return out;
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const auto& w : r.stats.warnings) out.message += (out.message.empty() ? "" : "; ") + w;

  const optics::Dipole<double> dipole = optics::Dipole<double>::make(
      scene.medium.material.sigmaA, scene.medium.material.sigmaSPrime, c.eta);
  const glm::dvec3 total = dipole.total();
  const std::vector<glm::dvec3>* stdError = nullptr;
  for (const auto& [name, values] : r.frame.extras)
    if (name == "stderr") stdError = &values;
  glm::dvec3 sum(0), limitSum(0), varianceSum(0);
  for (std::size_t i = 0; i < request.points.size(); ++i) {
    const glm::dvec3 L = r.frame.radiance[i];
    for (int k = 0; k < 3; ++k) {
      out.finite &= std::isfinite(L[k]);
      out.nonNegative &= L[k] >= 0;
    }
    const double cosine = glm::dot(glm::normalize(request.points[i].position), toLight);
    if (cosine < 0.8) continue;
    // B = E_t Rd_total; L = Ft(cos_out) B / pi, cos_out = cos (seen along the sun).
    const double ft = optics::fresnelTransmittance(cosine, c.eta);
    const glm::dvec3 limit = total * (ft * transmittedIrradiance(c, cosine) / optics::kPi);
    sum += L, limitSum += limit;
    if (stdError) varianceSum += (*stdError)[i] * (*stdError)[i];
    ++out.litPixels;
  }
  if (out.litPixels > 0) {
    out.limit = limitSum / double(out.litPixels);
    out.mean = sum / double(out.litPixels);
    for (int k = 0; k < 3; ++k) {
      out.ratio[k] = limitSum[k] > 0 ? sum[k] / limitSum[k] : 0;
      out.ratioError[k] = limitSum[k] > 0 ? std::sqrt(varianceSum[k]) / limitSum[k] : 0;
    }
  }
  return out;
}

}  // namespace lucent::test
