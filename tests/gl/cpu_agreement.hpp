// What the pass's GL tests compare a GPU twin with: its technique on the CPU at the GPU frame's
// own pixel positions.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <lucent/optics/materials.hpp>
#include <lucent/technique/registry.hpp>

#include "technique/core_registry.hpp"

#include "pass_scene.hpp"
#include "raycast/embree_ray_caster.hpp"

namespace lucent_test {
namespace lt = lucent::technique;

/// The pass's millimetre frame for data scaled to sizeMm: centred on the bounds, scaled.
struct MillimetreFrame {
  glm::dvec3 centre;
  double scale;
  glm::dvec3 operator()(const glm::dvec3& world) const { return (world - centre) * scale; }
};

struct Agreement {
  double relRms[3] = {}, meanRatio[3] = {};
  std::size_t pixels = 0;   ///< compared
  std::size_t covered = 0;  ///< drawn by the GPU
};

/// An inner body in world coordinates and its material.
struct Inner {
  lucent::scene::TriangleMesh world;
  std::string material;
};

/// `technique` on the CPU (the technique layer's, with Embree shadows) at every covered pixel of
/// the GPU frame, compared channel by channel; `light` in world coordinates.
inline Agreement compareWithCpu(const Frame& f, const lucent::scene::TriangleMesh& world,
                                double sizeMm, const std::string& material,
                                const lucent::scene::Light& light, const std::string& technique,
                                const lt::KnobList& knobs, const std::vector<Inner>& inner = {}) {
  const lucent::scene::Bounds bounds = world.bounds();
  const MillimetreFrame toMm{bounds.center(), sizeMm / bounds.diagonal()};
  lucent::scene::TriangleMesh mm = world;
  for (auto& p : mm.positions) p = glm::vec3(toMm(glm::dvec3(p)));
  const lucent::raycast::EmbreeRayCaster caster(mm);
  lt::SceneDescription scene;
  scene.meshName = "the pass's actor";
  scene.mesh = mm;
  scene.vertexNormals = mm.vertexNormals();
  scene.medium.material = *lucent::optics::findMaterial(material);
  scene.lights = {light};
  if (auto* p = std::get_if<lucent::scene::PointLight>(&scene.lights[0])) {
    p->position = toMm(p->position);  // the same intensity over squared millimetres
    p->intensity *= toMm.scale * toMm.scale;
  }
  scene.caster = &caster;
  for (const Inner& body : inner) {
    lt::Inclusion inc;
    inc.surface = body.world;
    for (auto& p : inc.surface.positions) p = glm::vec3(toMm(glm::dvec3(p)));
    inc.medium.material = *lucent::optics::findMaterial(body.material);
    scene.inclusions.push_back(inc);
  }
  lt::ShadeRequest request;
  std::vector<std::size_t> pixel;
  for (std::size_t i = 0; i < std::size_t(f.width) * std::size_t(f.height); ++i) {
    if (!(f.radiance[4 * i + 3] > 0)) continue;
    lucent::reference::ShadingPoint p;
    p.position = toMm(glm::dvec3(f.position[4 * i], f.position[4 * i + 1], f.position[4 * i + 2]));
    p.cosOut = std::min(1.0, std::abs(double(f.normal[4 * i + 3])));
    // The triangle under the pixel (techniques that shade from its interpolated normal read it):
    // a short ray through the point along the frame's normal. The GPU's position is kept.
    const glm::dvec3 n(f.normal[4 * i], f.normal[4 * i + 1], f.normal[4 * i + 2]);
    const double reach = 1e-3 * sizeMm;
    if (!(glm::length(n) > 0)) continue;
    const auto hit =
        caster.intersect(p.position + reach * glm::normalize(n), -glm::normalize(n), 0, 2 * reach);
    if (!hit) continue;  // off the mesh by more than the depth buffer's precision: not compared
    p.triangle = hit->triangle, p.u = hit->u, p.v = hit->v;
    request.points.push_back(p);
    pixel.push_back(i);
  }
  const lt::Registry registry = lt::compiledCoreRegistry();
  const lt::Technique& t = registry.get(technique);
  const lt::Rendered cpu = registry.render(t, scene, t.values(knobs), request);
  Agreement a;
  a.pixels = pixel.size();
  a.covered = f.covered();
  double diff2[3] = {}, ref2[3] = {}, gpuSum[3] = {}, cpuSum[3] = {};
  for (std::size_t k = 0; k < pixel.size(); ++k)
    for (int c = 0; c < 3; ++c) {
      const double g = f.radiance[4 * pixel[k] + std::size_t(c)], r = cpu.frame.radiance[k][c];
      diff2[c] += (g - r) * (g - r), ref2[c] += r * r, gpuSum[c] += g, cpuSum[c] += r;
    }
  for (int c = 0; c < 3; ++c) {
    a.relRms[c] = std::sqrt(diff2[c] / ref2[c]);
    a.meanRatio[c] = gpuSum[c] / cpuSum[c];
  }
  return a;
}

/// The same under a directional light of irradiance 1 from `towardLight`.
inline Agreement compareWithCpu(const Frame& f, const lucent::scene::TriangleMesh& world,
                                double sizeMm, const std::string& material,
                                const glm::dvec3& towardLight, const std::string& technique,
                                const lt::KnobList& knobs, const std::vector<Inner>& inner = {}) {
  return compareWithCpu(
      f, world, sizeMm, material,
      lucent::scene::DirectionalLight{glm::normalize(towardLight), glm::dvec3(1.0)}, technique,
      knobs, inner);
}

/// The GPU frame agrees with the CPU on nearly every pixel it drew (a pixel off the mesh by more
/// than the depth buffer's precision is not compared): per channel the mean within `meanTolerance`
/// and the relative RMS below `rmsBound` (each channel's figures are printed under `label`).
inline void checkAgreement(const Agreement& a, const std::string& label,
                           double meanTolerance = 0.02, double rmsBound = 0.05) {
  CHECK(double(a.pixels) >= 0.95 * double(a.covered));
  for (int c = 0; c < 3; ++c) {
    MESSAGE(label << ", channel " << c << ": relative RMS " << a.relRms[c] << ", mean GPU / CPU "
                  << a.meanRatio[c] << " over " << a.pixels << " of " << a.covered << " pixels");
    CHECK(a.meanRatio[c] == doctest::Approx(1.0).epsilon(meanTolerance));
    CHECK(a.relRms[c] < rmsBound);
  }
}

}  // namespace lucent_test
