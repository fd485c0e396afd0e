#pragma once
/// @file diffuse_brdf.hpp
/// @brief The "diffuse-brdf" technique: subsurface scattering as a diffuse BRDF whose albedo is the
/// profile's total diffuse reflectance, B(x) = E(x) Rd_total. It is the limit of the dipole sum
/// B(x) = int E(x') Rd(|x - x'|) dA' when E is constant over Rd's reach: what engines fall back to
/// when the reach is below a pixel, and what the planner picks there.
#include <algorithm>
#include <atomic>
#include <memory>
#include <vector>

#include "../scene/irradiance.hpp"
#include "technique.hpp"
#include "validity.hpp"

namespace lucent::technique {

namespace detail {

/// The BRDF limit holds where irradiance is constant over Rd's reach: on an object at least this
/// many times the radius holding 99 % of Rd across (the hard-case matrix holds it to 30 % of the
/// dipole sum there).
inline constexpr double kMinReachesAcross = 10;

inline std::string brdfLimitHolds(const SceneDescription& scene, const KnobValues& knobs) {
  const std::string thick = validity::opticallyThick(scene.mesh, scene.medium.material);
  if (!thick.empty()) return thick;
  const auto profile = profileOf<double>(scene.medium.material, knobs);
  const double reach = profile.largestRadiusHolding(0.99);
  const double across = scene.mesh.bounds().diagonal();
  if (across >= kMinReachesAcross * reach) return "";
  return "the object (" + lengthText(across) + " across) is " + numberText(across / reach) +
         " reaches of Rd across (99 % of Rd within " + lengthText(reach) +
         "); the diffuse-BRDF limit needs at least " + numberText(kMinReachesAcross) +
         ": a technique that sums Rd over the surface holds here";
}

class DiffuseBrdf final : public Prepared {
 public:
  explicit DiffuseBrdf(const KnobValues& knobs) : Prepared(knobs) {}

  FrameResult frame(const SceneDescription& scene, const ShadeRequest& request,
                    Statistics& stats) override {
    const auto profile = profileOf<double>(scene.medium.material, mKnobs);
    const glm::dvec3 albedo = profile.total();
    const scene::IrradianceSettings irr = irradianceSettings(scene, mKnobs);
    stats.samples = double(request.points.size());
    stats.sampleUnit = "irradiance evaluations";
    stats.figures["total_diffuse_reflectance_g"] = albedo.y;
    FrameResult out;
    out.exitScale = profile.exitScale;
    out.radiosity.resize(request.points.size());
    const util::Progress progress = scene.stage("irradiance");
    std::atomic<std::size_t> done{0};
    stats.timeFrame("irradiance", [&] {
      scene.parallelFor(request.points.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
          out.radiosity[i] = albedo * irradianceAt(scene, request.points[i], irr, i);
        if (progress) progress(double(done += end - begin) / double(request.points.size()));
      });
    });
    return out;
  }

 private:
  /// Fresnel-transmitted irradiance at a shading point, with its smooth and its face normal.
  static glm::dvec3 irradianceAt(const SceneDescription& scene, const reference::ShadingPoint& p,
                                 const scene::IrradianceSettings& irr, std::size_t id) {
    const glm::dvec3 w(1 - p.u - p.v, p.u, p.v);
    const glm::dvec3 normal = scene::shadingNormal(scene.mesh, scene.vertexNormals, p.triangle, w);
    const glm::dvec3 face = glm::normalize(scene.mesh.areaVector(p.triangle));
    return scene::irradianceAt(p.position, normal, face, scene.lights, *scene.caster, irr, id);
  }
};

}  // namespace detail

inline Technique diffuseBrdfTechnique() {
  Technique t;
  t.name = "diffuse-brdf";
  t.summary =
      "diffuse BRDF with the profile's total diffuse reflectance: B = E Rd_total (the dipole sum's "
      "limit when Rd's reach is below a pixel)";
  t.paper =
      "Jensen, Marschner, Levoy, Hanrahan 2001, the BRDF approximation of the BSSRDF (its total "
      "diffuse reflectance Rd)";
  t.knobs = {detail::envStrataKnob("point"), detail::profileKnob()};
  t.capabilities.multipleScatteringReach = Reach::Point;
  t.capabilities.precomputeScaling = "none";
  t.capabilities.frameScaling = "O(points x lights) shadow rays";
  // vtkLucentPass shades it per pixel (shaders/diffuse_brdf_shade.frag) with the profile's Rd_total
  // and the light's depth map for shadows.
  t.capabilities.gpuTwin = "vtkLucentPass";
  t.capabilities.gpuTwinKnobs = {{"profile"}};
  t.defaultSweep = {{"env-strata", {"4", "8", "16"}}};  // its only error besides the model's
  t.quickKnobs = {{"env-strata", "4"}};
  t.model = "dipole";
  t.validRange = validity::thickRange() + ", and at least " +
                 numberText(detail::kMinReachesAcross) +
                 " times the radius holding 99 % of Rd across (irradiance constant over Rd's "
                 "reach); it equals the dipole sum's image where that reach is below a pixel";
  t.validity = detail::brdfLimitHolds;
  t.prepare = [](const SceneDescription&, const KnobValues& knobs, Statistics&) {
    return std::make_unique<detail::DiffuseBrdf>(knobs);
  };
  return t;
}

}  // namespace lucent::technique
