#pragma once
/// @file relight.hpp
/// @brief A PRT frame (Wang, Tran, Luebke 2005, Sec. 4): the environment, turned as asked, onto the
/// cube, Haar, the largest terms kept (the light vector); per vertex the sparse dot products with
/// the transport vectors; per point the view-dependent part: L = Ft(eta, w_o) (D + sum_k
/// view_k(w_o') S_k), D and S_k interpolated from the vertices.
#include <vector>

#include <glm/geometric.hpp>

#include "../optics/fresnel.hpp"
#include "../scene/environment_resample.hpp"
#include "../util/parallel.hpp"
#include "haar.hpp"
#include "precompute.hpp"
#include "sparse_vector.hpp"

namespace lucent::prt {

/// Haar coefficients of the environment `cube` (scene::sumOnCube) with the `terms` largest kept
/// (0: all), dense with zeros elsewhere.
inline std::vector<glm::vec3> lightVector(std::vector<glm::vec3> cube, int size, std::size_t terms,
                                          Selection selection, std::size_t* kept = nullptr) {
  haarForwardCube(cube, size);
  const SparseVector largest = keepLargest(cube, size, terms == 0 ? cube.size() : terms, selection);
  std::vector<glm::vec3> light(cube.size(), glm::vec3(0));
  for (std::size_t i = 0; i < largest.size(); ++i) light[largest.index[i]] = largest.value[i];
  if (kept) *kept = largest.size();
  return light;
}

/// The same of the environments summed on a cube `size` across, turned by `angle` radians about +y.
inline std::vector<glm::vec3> lightVector(const std::vector<const scene::EnvironmentLight*>& envs,
                                          int size, double angle, std::size_t terms,
                                          Selection selection, std::size_t* kept = nullptr) {
  return lightVector(scene::sumOnCube(envs, size, angle), size, terms, selection, kept);
}

/// The light's dot products with every vertex's vectors.
struct VertexShading {
  std::vector<glm::dvec3> diffuse;
  std::vector<std::vector<glm::dvec3>> single;  ///< per vertex, K each (empty when folded)
};

inline VertexShading relightVertices(const PrtModel& model, const std::vector<glm::vec3>& light,
                                     const util::ParallelFor& parallelFor) {
  VertexShading out;
  const LightChannels channels(light);
  out.diffuse.resize(model.diffuse.size());
  out.single.resize(model.single.size());
  parallelFor(model.diffuse.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) {
      out.diffuse[v] = dot(model.diffuse[v], channels);
      if (v < model.single.size())
        for (const QuantizedVector& k : model.single[v]) out.single[v].push_back(dot(k, channels));
    }
  });
  return out;
}

/// Radiance leaving a point with interpolation weights `w` over the vertices `tri`, shading normal
/// `normal`, towards `toEye`.
inline glm::dvec3 pointRadiance(const PrtModel& model, const VertexShading& shading,
                                const glm::uvec3& tri, const glm::dvec3& w,
                                const glm::dvec3& normal, const glm::dvec3& toEye) {
  const double cosOut = glm::dot(normal, toEye);
  if (!(cosOut > 0)) return glm::dvec3(0);
  glm::dvec3 l =
      w.x * shading.diffuse[tri.x] + w.y * shading.diffuse[tri.y] + w.z * shading.diffuse[tri.z];
  if (!shading.single.empty()) {
    const glm::dvec3 refracted = glm::refract(-toEye, normal, 1.0 / model.eta);
    for (std::size_t k = 0; k < model.phase.terms(); ++k) {
      const glm::dvec3 s = w.x * shading.single[tri.x][k] + w.y * shading.single[tri.y][k] +
                           w.z * shading.single[tri.z][k];
      l += s * model.phase.viewAt(k, -refracted);
    }
  }
  return l * optics::fresnelTransmittance(cosOut, model.eta);
}

}  // namespace lucent::prt
