#pragma once
/// @file scene.hpp
/// @brief The scene every technique reads: the surface, its media (one spelling for all
/// techniques), the lights, the services a technique may use (ray casting, a parallel loop,
/// progress and cancel), and the points a frame shades.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "../optics/materials.hpp"
#include "../reference/dipole_truth.hpp"
#include "../scene/camera.hpp"
#include "../scene/light.hpp"
#include "../scene/mesh.hpp"
#include "../scene/ray_caster.hpp"
#include "../util/parallel.hpp"
#include "capabilities.hpp"
#include "knob.hpp"

namespace lucent::technique {

/// A scalar field over the object, mm coordinates; multiplies sigma_a and sigma_s (1 = the
/// material).
using DensityField = std::function<double(const glm::dvec3&)>;

/// Absorption and reduced scattering at a point, mm^-1 per channel.
struct Coefficients {
  glm::dvec3 sigmaA{0}, sigmaSPrime{0};
  bool operator==(const Coefficients& o) const {
    return sigmaA == o.sigmaA && sigmaSPrime == o.sigmaSPrime;
  }
};
/// Coefficients over the object, mm coordinates: a scan through a transfer function or a label map.
using CoefficientField = std::function<Coefficients(const glm::dvec3&)>;

/// A homogeneous material, optionally scaled by a density field (a scanned volume), or replaced by
/// a field of coefficients (the material then gives only eta and the name).
struct Medium {
  optics::Material material;
  DensityField density;            ///< empty: homogeneous
  std::string densityDescription;  ///< where the field came from, for notes
  CoefficientField coefficients;   ///< when set, replaces material x density
  glm::dvec3 maxSigmaT{0};  ///< with `coefficients`: sigma_a + sigma_s' never above, per channel
  bool heterogeneous() const { return bool(density) || bool(coefficients); }
  /// The coefficients at p.
  Coefficients at(const glm::dvec3& p) const {
    if (coefficients) return coefficients(p);
    const double rho = density ? density(p) : 1.0;
    return {glm::dvec3(material.sigmaA) * rho, glm::dvec3(material.sigmaSPrime) * rho};
  }
};

/// A closed surface inside the object, filled with another medium (an inclusion; e.g. a tumour in
/// tissue).
struct Inclusion {
  scene::TriangleMesh surface;
  Medium medium;
  std::function<bool(const glm::dvec3&)> contains;  ///< whether a point lies inside the surface
  std::string description;
};

using RayCasterFactory =
    std::function<std::unique_ptr<scene::RayCaster>(const scene::TriangleMesh&)>;

/// Progress of a named stage in [0, 1]; may be called from worker threads.
using StageProgress = std::function<void(const std::string& stage, double fraction)>;

/// Thrown by SceneDescription::checkCancelled when the front end asked to stop.
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled") {}
};

struct SceneDescription {
  std::string meshName;
  scene::TriangleMesh mesh;  ///< mm, closed, outward
  std::vector<glm::vec3> vertexNormals;
  Medium medium;                      ///< what the object is made of
  std::vector<Inclusion> inclusions;  ///< nested bodies of other media
  std::vector<scene::Light> lights;
  const scene::RayCaster* caster = nullptr;  ///< over `mesh`
  RayCasterFactory makeRayCaster;  ///< for meshes a technique builds (node surfaces, media bodies)
  util::ParallelFor parallelFor = util::serialFor;
  StageProgress progress;
  std::function<bool()> cancelRequested;

  /// Offset of secondary rays from the surface: relative to the object so it holds at any size.
  double rayEpsilon() const { return 1e-5 * mesh.bounds().diagonal(); }
  /// A progress callback for one stage (empty when nobody listens).
  util::Progress stage(const std::string& name) const {
    if (!progress) return {};
    return [sink = progress, name](double f) { sink(name, f); };  // safe to keep beyond this scene
  }
  void checkCancelled() const {
    if (cancelRequested && cancelRequested()) throw Cancelled();
  }
};

/// The points a frame shades: surface points seen through pixels (with the camera, for techniques
/// that trace camera rays), or a mesh's vertices.
struct ShadeRequest {
  std::vector<reference::ShadingPoint> points;
  const scene::PinholeCamera* camera = nullptr;  ///< set when the points are pixels' first hits
  std::vector<std::size_t> pixels;               ///< with a camera: the pixel of each point
  bool vertices = false;                         ///< the points are the mesh's vertices, in order
};

/// What a scene and a request call for, for the capability check.
inline Requirements requirementsOf(const SceneDescription& scene, const ShadeRequest& request) {
  Requirements r;
  for (const auto& light : scene.lights) {
    r.pointLight |= std::holds_alternative<scene::PointLight>(light);
    r.directionalLight |= std::holds_alternative<scene::DirectionalLight>(light);
    r.environmentLight |= std::holds_alternative<scene::EnvironmentLight>(light);
  }
  r.heterogeneousMedium = scene.medium.heterogeneous();
  for (const auto& inc : scene.inclusions) r.heterogeneousMedium |= inc.medium.heterogeneous();
  r.inclusions = !scene.inclusions.empty();
  r.perVertex = request.vertices;
  r.camera = request.camera != nullptr;
  return r;
}

/// Shading points at the mesh's vertices (each on one of its triangles, barycentrics at the
/// vertex), seen head-on: the request of per-vertex front ends such as the VTK filter.
inline ShadeRequest vertexRequest(const scene::TriangleMesh& mesh) {
  ShadeRequest r;
  r.vertices = true;
  r.points.resize(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    r.points[i].position = glm::dvec3(mesh.positions[i]);
  for (std::size_t t = mesh.triangles.size(); t-- > 0;) {
    const auto& tri = mesh.triangles[t];
    const double bary[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    for (int k = 0; k < 3; ++k) {
      auto& p = r.points[tri[k]];
      p.triangle = std::uint32_t(t), p.u = bary[k][0], p.v = bary[k][1];
    }
  }
  for (auto& p : r.points) p.cosOut = 1;
  return r;
}

/// Shading points at the first hit through every pixel centre.
inline ShadeRequest pixelRequest(const scene::PinholeCamera& camera,
                                 const SceneDescription& scene) {
  ShadeRequest r;
  r.camera = &camera;
  const auto hits = reference::primaryHits(camera, scene.mesh, scene.vertexNormals, *scene.caster,
                                           scene.parallelFor);
  for (std::size_t i = 0; i < hits.size(); ++i)
    if (hits[i]) {
      r.points.push_back(*hits[i]);
      r.pixels.push_back(i);
    }
  return r;
}

}  // namespace lucent::technique
