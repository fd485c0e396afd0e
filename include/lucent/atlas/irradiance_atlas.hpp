#pragma once
/// @file irradiance_atlas.hpp
/// @brief Stage 1 of Chang et al. 2008 (Sec. 3): irradiance rendered into the atlas as
/// E' = A_S E / A_T (Eq. 7), with shadows, over the 3-D position map. The map depends on the mesh
/// only (buildAtlasSurface, once); the irradiance on the light (lightAtlas, every frame). Each
/// texel stores its power E' x (texel area) = E(x_texel) A_S / n_T, n_T the texels its triangle
/// owns, so that the sum over texels is the quadrature of the surface integral of E: this sum is
/// E'_avg of Eq. 9-11.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/geometric.hpp>

#include "../scene/irradiance.hpp"
#include "../scene/mesh.hpp"
#include "../util/parallel.hpp"
#include "texture_atlas.hpp"

namespace lucent::atlas {

/// The surface under the atlas, which depends on the mesh and the atlas only: what a frame's
/// irradiance reads, built once (prepare) so that a frame redoes only the light.
struct AtlasSurface {
  int resolution = 0;
  std::vector<glm::vec3>
      position;  ///< surface point at the texel centre (mm); meaningful where owned
  std::vector<glm::vec3> dPdx,
      dPdy;  ///< mm per texel along the atlas axes (the owner's affine map)
  /// The owned texels, and for each its shading and face normal and its share A_S / n_T of its
  /// triangle's area.
  std::vector<std::uint32_t> owned;
  std::vector<glm::vec3> normal, faceNormal;
  std::vector<float> area;
  /// Triangles too small to own a texel: the texel under their centroid gets their power.
  struct Guest {
    std::uint32_t texel, triangle;
    glm::vec3 position, normal, faceNormal;
    float area;
  };
  std::vector<Guest> guests;
};

struct IrradianceAtlas {
  int resolution = 0;
  std::shared_ptr<const AtlasSurface> surface;  ///< positions and their derivatives per texel
  std::vector<glm::vec3> power;                 ///< per texel, per channel: E' times the texel area
  std::vector<float> importance;  ///< R+G+B of the power: the density the samplers follow (Eq. 9)
  glm::dvec3 totalPower{0};       ///< E'_avg of Eq. 9: the integral of E' over texture space
};

namespace detail {
/// Barycentric coordinates of p in the 2-D triangle (a, b, c); extrapolates outside it.
inline glm::dvec3 barycentric2(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c,
                               const glm::dvec2& p) {
  const double d = signedArea2(a, b, c);
  const double wb = signedArea2(a, p, c) / d, wc = signedArea2(a, b, p) / d;
  return {1 - wb - wc, wb, wc};
}
}  // namespace detail

/// The surface under `atlas` (prepare). @param vertexNormals shading normals
/// (mesh.vertexNormals()).
inline std::shared_ptr<const AtlasSurface> buildAtlasSurface(
    const TextureAtlas& atlas, const scene::TriangleMesh& mesh,
    const std::vector<glm::vec3>& vertexNormals,
    const util::ParallelFor& parallelFor = util::serialFor) {
  const int res = atlas.resolution;
  const std::size_t texels = std::size_t(res) * res;
  auto out = std::make_shared<AtlasSurface>();
  out->resolution = res;
  out->position.assign(texels, glm::vec3(0));
  out->dPdx.assign(texels, glm::vec3(0));
  out->dPdy.assign(texels, glm::vec3(0));
  for (std::size_t i = 0; i < texels; ++i)
    if (atlas.texelTriangle[i] >= 0) out->owned.push_back(std::uint32_t(i));
  out->normal.resize(out->owned.size());
  out->faceNormal.resize(out->owned.size());
  out->area.resize(out->owned.size());

  auto surfacePoint = [&](std::size_t t, const glm::dvec3& w, glm::dvec3& p, glm::dvec3& n,
                          glm::dvec3& fn) {
    const auto& tri = mesh.triangles[t];
    p = w.x * glm::dvec3(mesh.positions[tri.x]) + w.y * glm::dvec3(mesh.positions[tri.y]) +
        w.z * glm::dvec3(mesh.positions[tri.z]);
    n = scene::shadingNormal(mesh, vertexNormals, t, w);
    fn = glm::normalize(mesh.areaVector(t));
  };
  AtlasSurface& s = *out;
  parallelFor(s.owned.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const std::size_t i = s.owned[k];
      const int x = int(i % std::size_t(res)), y = int(i / std::size_t(res));
      const std::size_t t = std::size_t(atlas.texelTriangle[i]);
      const glm::dvec2 a = atlas.uv[3 * t], b = atlas.uv[3 * t + 1], c = atlas.uv[3 * t + 2];
      glm::dvec3 p, n, fn;
      surfacePoint(t, detail::barycentric2(a, b, c, {x + 0.5, y + 0.5}), p, n, fn);
      // The affine map texel -> surface: derivative of the barycentric interpolation.
      glm::dvec3 px, py, pn, pfn;
      surfacePoint(t, detail::barycentric2(a, b, c, {x + 1.5, y + 0.5}), px, pn, pfn);
      surfacePoint(t, detail::barycentric2(a, b, c, {x + 0.5, y + 1.5}), py, pn, pfn);
      s.position[i] = glm::vec3(p);
      s.dPdx[i] = glm::vec3(px - p);
      s.dPdy[i] = glm::vec3(py - p);
      s.normal[k] = glm::vec3(n), s.faceNormal[k] = glm::vec3(fn);
      s.area[k] = float(mesh.triangleArea(t) / double(atlas.texelCount[t]));
    }
  });
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (atlas.guestTexel[t] < 0) continue;
    glm::dvec3 p, n, fn;
    surfacePoint(t, glm::dvec3(1.0 / 3.0), p, n, fn);
    s.guests.push_back({std::uint32_t(atlas.guestTexel[t]), std::uint32_t(t), glm::vec3(p),
                        glm::vec3(n), glm::vec3(fn), float(mesh.triangleArea(t))});
  }
  return out;
}

/// E' into the atlas (Eq. 7), with shadows: what a frame redoes when the light changes.
/// @param recycled an earlier atlas whose buffers this one reuses (a frame after a light change
/// would otherwise page-fault 16 MB of fresh memory in: 0.04 s of the hybrid's 0.24 s frame).
inline IrradianceAtlas lightAtlas(const std::shared_ptr<const AtlasSurface>& surface,
                                  const std::vector<scene::Light>& lights,
                                  const scene::RayCaster& caster,
                                  const scene::IrradianceSettings& irr,
                                  const util::ParallelFor& parallelFor = util::serialFor,
                                  const util::Progress& progress = {},
                                  IrradianceAtlas recycled = {}) {
  const AtlasSurface& s = *surface;
  const std::size_t texels = std::size_t(s.resolution) * std::size_t(s.resolution);
  IrradianceAtlas out = std::move(recycled);  // its buffers, refilled: no fresh pages to fault in
  out.totalPower = glm::dvec3(0);
  out.resolution = s.resolution;
  out.surface = surface;
  out.power.assign(texels, glm::vec3(0));
  out.importance.resize(texels);  // every texel's is set from its power below
  std::atomic<std::size_t> done{0};
  // Owned texels in atlas order, kShadowStream at a time: neighbours' shadow rays toward a light
  // are nearly parallel, so the caster traces them as packets (scene::irradianceMany).
  constexpr std::size_t kShadowStream = 1024;
  parallelFor(s.owned.size(), [&](std::size_t begin, std::size_t end) {
    glm::dvec3 e[kShadowStream];
    for (std::size_t first = begin; first < end; first += kShadowStream) {
      const std::size_t n = std::min(kShadowStream, end - first);
      scene::irradianceMany(
          n,
          [&](std::size_t j) {
            const std::size_t k = first + j, i = s.owned[k];
            return scene::SurfacePoint{glm::dvec3(s.position[i]), glm::dvec3(s.normal[k]),
                                       glm::dvec3(s.faceNormal[k]), i};
          },
          lights, caster, irr, e);
      for (std::size_t j = 0; j < n; ++j)
        out.power[s.owned[first + j]] = glm::vec3(e[j] * double(s.area[first + j]));
    }
    if (progress) progress(double(done += end - begin) / double(s.owned.size()));
  });
  for (const AtlasSurface::Guest& g : s.guests) {
    const glm::dvec3 e =
        scene::irradianceAt(glm::dvec3(g.position), glm::dvec3(g.normal), glm::dvec3(g.faceNormal),
                            lights, caster, irr, texels + g.triangle);
    out.power[g.texel] += glm::vec3(e * double(g.area));
  }
  for (std::size_t i = 0; i < texels; ++i) {
    out.totalPower += glm::dvec3(out.power[i]);
    out.importance[i] = out.power[i].x + out.power[i].y + out.power[i].z;
  }
  return out;
}

/// Both stages at once (tests, one-off uses).
inline IrradianceAtlas renderIrradianceAtlas(
    const TextureAtlas& atlas, const scene::TriangleMesh& mesh,
    const std::vector<glm::vec3>& vertexNormals, const std::vector<scene::Light>& lights,
    const scene::RayCaster& caster, const scene::IrradianceSettings& irr,
    const util::ParallelFor& parallelFor = util::serialFor, const util::Progress& progress = {}) {
  return lightAtlas(buildAtlasSurface(atlas, mesh, vertexNormals, parallelFor), lights, caster, irr,
                    parallelFor, progress);
}

}  // namespace lucent::atlas
