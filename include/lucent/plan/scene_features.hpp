#pragma once
/// @file scene_features.hpp
/// @brief The few numbers of a scene the planner decides on: the object's size and thickness
/// against the material's transport lengths, the diffusion profile's reach against a pixel, the
/// albedo, where the light comes from relative to the viewer, and what the media and lights call
/// for. The same numbers label every calibration measurement (plan/calibration.hpp), so a scene is
/// compared with the measured ones in these terms only.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <variant>

#include <glm/geometric.hpp>

#include "../optics/profile.hpp"
#include "../scene/camera.hpp"
#include "../technique/scene.hpp"
#include "../technique/validity.hpp"

namespace lucent::plan {

struct SceneFeatures {
  double sizeMm = 0;             ///< bounding-box diagonal
  double thicknessMm = 0;        ///< mean chord length 4V/A (Cauchy's formula)
  double meanFreePathMm = 0;     ///< the longest transport mean free path 1/sigma_t' over channels
  double diffusionLengthMm = 0;  ///< the longest 1/sigma_tr over channels (inf: no absorption)
  double albedo = 0;             ///< the smallest reduced albedo sigma_s'/sigma_t' over channels
  double reachMm = 0;           ///< radius holding 99 % of the classic dipole's Rd, largest channel
  double pixelMm = 0;           ///< what one pixel covers at the object (no camera: mean edge)
  double backLitShare = 0;      ///< share of the light arriving from the far side of the viewer
  double environmentShare = 0;  ///< share of the light from environment lights
  double light = 0;             ///< total light (luminance of irradiance at the centre, W/mm^2)
  double shadedPoints = 0;      ///< points a frame shades (pixels covered or vertices)
  double triangles = 0;
  double areaMm2 = 0;
  bool heterogeneous = false, inclusions = false;
  bool environment() const { return environmentShare > 0; }

  ///@{ Ratios the rules read: dimensionless, so they hold at any unit.
  double sizeInMeanFreePaths() const { return sizeMm / meanFreePathMm; }
  /// The thickness in diffusion lengths: light crossing it falls as e^{-this} (inf: none gets
  /// lost).
  double thicknessInDiffusionLengths() const {
    return std::isfinite(diffusionLengthMm) ? thicknessMm / diffusionLengthMm : 0;
  }
  double reachInPixels() const { return pixelMm > 0 ? reachMm / pixelMm : INFINITY; }
  /// Surface area in squared mean free paths: what the dipole sums' sample counts grow with.
  double areaInMeanFreePaths2() const { return areaMm2 / (meanFreePathMm * meanFreePathMm); }
  ///@}
};

/// The names and values of the features as the calibration files store them, in this order.
inline constexpr std::array<const char*, 15> kFeatureNames{"size_mm",
                                                           "thickness_mm",
                                                           "mean_free_path_mm",
                                                           "diffusion_length_mm",
                                                           "albedo",
                                                           "reach_mm",
                                                           "pixel_mm",
                                                           "back_lit_share",
                                                           "light",
                                                           "shaded_points",
                                                           "triangles",
                                                           "area_mm2",
                                                           "environment_share",
                                                           "heterogeneous",
                                                           "inclusions"};

inline std::array<double, kFeatureNames.size()> featureValues(const SceneFeatures& f) {
  return {f.sizeMm,
          f.thicknessMm,
          f.meanFreePathMm,
          f.diffusionLengthMm,
          f.albedo,
          f.reachMm,
          f.pixelMm,
          f.backLitShare,
          f.light,
          f.shadedPoints,
          f.triangles,
          f.areaMm2,
          f.environmentShare,
          double(f.heterogeneous),
          double(f.inclusions)};
}

inline SceneFeatures featuresFromValues(const std::array<double, kFeatureNames.size()>& v) {
  SceneFeatures f;
  f.sizeMm = v[0], f.thicknessMm = v[1], f.meanFreePathMm = v[2], f.diffusionLengthMm = v[3];
  f.albedo = v[4], f.reachMm = v[5], f.pixelMm = v[6], f.backLitShare = v[7], f.light = v[8];
  f.shadedPoints = v[9], f.triangles = v[10], f.areaMm2 = v[11];
  f.environmentShare = v[12], f.heterogeneous = v[13] != 0, f.inclusions = v[14] != 0;
  return f;
}

namespace detail {
inline double luminance(const glm::dvec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

/// The material's transport lengths and albedo (longest lengths: the channel that carries light
/// furthest decides what reaches the far side).
inline void setOpticalFeatures(const optics::Material& m, SceneFeatures& f) {
  f.meanFreePathMm = 0, f.diffusionLengthMm = 0, f.albedo = 1, f.reachMm = 0;
  const auto profile =
      optics::Profile<double>::make(optics::ProfileModel::Dipole, optics::Rgb<double>(m.sigmaA),
                                    optics::Rgb<double>(m.sigmaSPrime), m.eta);
  f.reachMm = profile.largestRadiusHolding(0.99);
  for (int c = 0; c < 3; ++c) {
    if (!(m.sigmaSPrime[c] > 0)) continue;  // no diffuse light in it (as technique::opticalScales)
    const double st = m.sigmaA[c] + m.sigmaSPrime[c];
    const double sigmaTr = std::sqrt(3 * m.sigmaA[c] * st);
    f.meanFreePathMm = std::max(f.meanFreePathMm, 1 / st);
    f.diffusionLengthMm = std::max(f.diffusionLengthMm, sigmaTr > 0 ? 1 / sigmaTr : INFINITY);
    f.albedo = std::min(f.albedo, m.sigmaSPrime[c] / st);
  }
}

/// Luminance of each light's irradiance at the object's centre and its share from behind the
/// object as the viewer sees it (an environment counts half from each side).
inline void setLightFeatures(const technique::SceneDescription& scene, const glm::dvec3& center,
                             const std::optional<glm::dvec3>& towardViewer, SceneFeatures& f) {
  double total = 0, behind = 0, environment = 0;
  for (const scene::Light& light : scene.lights) {
    double e = 0;
    glm::dvec3 toward(0);
    if (const auto* p = std::get_if<scene::PointLight>(&light)) {
      const glm::dvec3 d = p->position - center;
      const double d2 = glm::dot(d, d);
      e = d2 > 0 ? luminance(p->intensity) / d2 : 0;
      toward = d2 > 0 ? d / std::sqrt(d2) : glm::dvec3(0);
    } else if (const auto* dl = std::get_if<scene::DirectionalLight>(&light)) {
      e = luminance(dl->irradiance);
      toward = glm::normalize(dl->towardLight);
    } else if (const auto* env = std::get_if<scene::EnvironmentLight>(&light)) {
      // pi x the mean radiance (over solid angle): the irradiance a uniform environment would give.
      e = optics::kPi * luminance(env->meanRadiance());
      total += e, behind += 0.5 * e, environment += e;
      continue;
    }
    if (!(e > 0) || !std::isfinite(e)) continue;
    total += e;
    if (towardViewer && glm::dot(toward, *towardViewer) < 0) behind += e;
  }
  f.light = total;
  f.backLitShare = total > 0 ? behind / total : 0;
  f.environmentShare = total > 0 ? environment / total : 0;
}
}  // namespace detail

/// What one pixel of `camera` covers at `point`, across (0 at the eye).
inline double pixelFootprint(const scene::PinholeCamera& camera, const glm::dvec3& point) {
  return 2 * glm::length(camera.eye - point) *
         std::tan(0.5 * camera.verticalFovDeg * optics::kPi / 180) /
         double(std::max(1, camera.height));
}

/// The features of a scene shaded at `request`; `camera` gives the viewer and the pixel size
/// (null: a per-vertex request, the pixel is the mean edge and the light's side is unknown).
inline SceneFeatures sceneFeatures(const technique::SceneDescription& scene,
                                   const technique::ShadeRequest& request,
                                   const scene::PinholeCamera* camera) {
  SceneFeatures f;
  const scene::Bounds bounds = scene.mesh.bounds();
  f.sizeMm = bounds.diagonal();
  f.areaMm2 = technique::surfaceArea(scene.mesh);
  f.thicknessMm = f.areaMm2 > 0 ? 4 * std::abs(scene.mesh.signedVolume()) / f.areaMm2 : 0;
  detail::setOpticalFeatures(scene.medium.material, f);
  std::optional<glm::dvec3> towardViewer;
  if (camera) {
    const double distance = glm::length(camera->eye - bounds.center());
    f.pixelMm = pixelFootprint(*camera, bounds.center());
    if (distance > 0) towardViewer = (camera->eye - bounds.center()) / distance;
  } else {
    f.pixelMm = technique::meanEdgeLength(scene.mesh);
  }
  detail::setLightFeatures(scene, bounds.center(), towardViewer, f);
  f.heterogeneous = scene.medium.heterogeneous();
  f.inclusions = !scene.inclusions.empty();
  f.shadedPoints = double(request.points.size());
  f.triangles = double(scene.mesh.triangles.size());
  return f;
}

}  // namespace lucent::plan
