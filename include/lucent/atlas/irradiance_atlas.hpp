#pragma once
/// @file irradiance_atlas.hpp
/// @brief Stage 1 of Chang et al. 2008 (Sec. 3): irradiance rendered into the atlas as
/// E' = A_S E / A_T (Eq. 7), with shadows, and the 3-D position map. Each texel stores its power
/// E' x (texel area) = E(x_texel) A_S / n_T, n_T the texels its triangle owns, so that the sum over
/// texels is the quadrature of the surface integral of E: this sum is E'_avg of Eq. 9-11.
#include <atomic>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>

#include "../scene/irradiance.hpp"
#include "../scene/mesh.hpp"
#include "../util/parallel.hpp"
#include "texture_atlas.hpp"

namespace lucent::atlas {

struct IrradianceAtlas {
  int resolution = 0;
  std::vector<glm::vec3> power;     ///< per texel, per channel: E' times the texel area
  std::vector<glm::vec3> position;  ///< surface point at the texel centre (mm); meaningful where owned
  std::vector<glm::vec3> dPdx, dPdy;///< mm per texel along the atlas axes (the owner's affine map)
  std::vector<float> importance;    ///< R+G+B of the power: the density the samplers follow (Eq. 9)
  glm::dvec3 totalPower{0};         ///< E'_avg of Eq. 9: the integral of E' over texture space
};

namespace detail {
/// Barycentric coordinates of p in the 2-D triangle (a, b, c); extrapolates outside it.
inline glm::dvec3 barycentric2(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& p) {
  const double d = signedArea2(a, b, c);
  const double wb = signedArea2(a, p, c) / d, wc = signedArea2(a, b, p) / d;
  return {1 - wb - wc, wb, wc};
}
}  // namespace detail

/// @param vertexNormals shading normals (mesh.vertexNormals()); @param irr Fresnel index and ray offsets.
inline IrradianceAtlas renderIrradianceAtlas(const TextureAtlas& atlas, const scene::TriangleMesh& mesh,
                                             const std::vector<glm::vec3>& vertexNormals,
                                             const std::vector<scene::Light>& lights, const scene::RayCaster& caster,
                                             const scene::IrradianceSettings& irr,
                                             const util::ParallelFor& parallelFor = util::serialFor,
                                             const util::Progress& progress = {}) {
  const int res = atlas.resolution;
  const std::size_t texels = std::size_t(res) * res;
  IrradianceAtlas out;
  out.resolution = res;
  out.power.assign(texels, glm::vec3(0));
  out.position.assign(texels, glm::vec3(0));
  out.dPdx.assign(texels, glm::vec3(0));
  out.dPdy.assign(texels, glm::vec3(0));
  out.importance.assign(texels, 0.0f);

  auto surfacePoint = [&](std::size_t t, const glm::dvec3& w, glm::dvec3& p, glm::dvec3& n, glm::dvec3& fn) {
    const auto& tri = mesh.triangles[t];
    p = w.x * glm::dvec3(mesh.positions[tri.x]) + w.y * glm::dvec3(mesh.positions[tri.y]) +
        w.z * glm::dvec3(mesh.positions[tri.z]);
    n = scene::shadingNormal(mesh, vertexNormals, t, w);
    fn = glm::normalize(mesh.areaVector(t));
  };

  std::atomic<std::size_t> done{0};
  parallelFor(std::size_t(res), [&](std::size_t begin, std::size_t end) {
    for (std::size_t y = begin; y < end; ++y) {
      for (int x = 0; x < res; ++x) {
        const std::size_t i = atlas.texelIndex(x, int(y));
        const std::int32_t owner = atlas.texelTriangle[i];
        if (owner < 0) continue;
        const std::size_t t = std::size_t(owner);
        const glm::dvec2 a = atlas.uv[3 * t], b = atlas.uv[3 * t + 1], c = atlas.uv[3 * t + 2];
        glm::dvec3 p, n, fn;
        surfacePoint(t, detail::barycentric2(a, b, c, {x + 0.5, y + 0.5}), p, n, fn);
        // The affine map texel -> surface: derivative of the barycentric interpolation.
        glm::dvec3 px, py, pn, pfn;
        surfacePoint(t, detail::barycentric2(a, b, c, {x + 1.5, y + 0.5}), px, pn, pfn);
        surfacePoint(t, detail::barycentric2(a, b, c, {x + 0.5, y + 1.5}), py, pn, pfn);
        out.position[i] = glm::vec3(p);
        out.dPdx[i] = glm::vec3(px - p);
        out.dPdy[i] = glm::vec3(py - p);
        const glm::dvec3 e = scene::irradianceAt(p, n, fn, lights, caster, irr, i);
        out.power[i] = glm::vec3(e * (mesh.triangleArea(t) / double(atlas.texelCount[t])));
      }
      if (progress) progress(double(done += 1) / double(res));
    }
  });
  // Guests: triangles too small to own a texel add their power to the texel under their centroid.
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (atlas.guestTexel[t] < 0) continue;
    glm::dvec3 p, n, fn;
    surfacePoint(t, glm::dvec3(1.0 / 3.0), p, n, fn);
    const glm::dvec3 e = scene::irradianceAt(p, n, fn, lights, caster, irr, texels + t);
    out.power[std::size_t(atlas.guestTexel[t])] += glm::vec3(e * mesh.triangleArea(t));
  }
  for (std::size_t i = 0; i < texels; ++i) {
    out.totalPower += glm::dvec3(out.power[i]);
    out.importance[i] = out.power[i].x + out.power[i].y + out.power[i].z;
  }
  return out;
}

}  // namespace lucent::atlas
