#pragma once
/// @file precompute.hpp
/// @brief The precomputation of all-frequency translucency PRT (Wang, Tran, Luebke 2005, Sec. 3),
/// stage by stage: irradiance transport vectors at uniform surface samples (Haar, the largest terms
/// kept), the Jensen-Buhler hierarchy over them in transport space, and per vertex the
/// multiple-scattering vector T = (exit scale / pi) sum_j Rd A_j E_j plus the single-scattering
/// vectors (isotropic: folded into T). Every vector is stored quantised to 16 bits
/// (sparse_vector.hpp).
#include <algorithm>
#include <atomic>
#include <limits>
#include <cmath>
#include <vector>

#include "../optics/profile.hpp"
#include "../reference/near_field.hpp"
#include "../reference/surface_samples.hpp"
#include "../util/parallel.hpp"
#include "irradiance_transport.hpp"
#include "single_transport.hpp"
#include "sparse_vector.hpp"
#include "transport_hierarchy.hpp"

namespace lucent::prt {

struct PrtSettings {
  TransportSampling transport;  ///< the cube's size, rays per texel, eta
  // Unset, the precomputation is exact: every term kept, every sample summed (the prt technique's
  // knobs set them).
  std::size_t sampleTerms = 0;  ///< kept per sample's irradiance transport vector (0: all)
  std::size_t nodeTerms = 0;    ///< kept per hierarchy node (0: all)
  std::size_t vertexTerms = 0;  ///< kept per vertex vector (0: all)
  double epsilon = 0;           ///< the hierarchy's area / distance^2 bound
  /// R_d's light kept per channel: a vertex gathers within the radius where this fraction of each
  /// channel's total leaves (Profile::largestRadiusHolding); 1: the whole surface.
  double reachFraction = 1;
  bool single = true;           ///< add the single-scattering vectors
  SingleTransportSampling singleSampling;
};

/// What a frame relights: per vertex a diffuse vector and, for an anisotropic phase function, K
/// single-scattering vectors with the phase function's view maps.
struct PrtModel {
  int cubeSize = 16;
  double eta = 1.3;
  std::vector<QuantizedVector> diffuse;              ///< per vertex
  std::vector<std::vector<QuantizedVector>> single;  ///< per vertex, K each (empty: folded)
  PhaseFactors phase;
  std::size_t hierarchyBytes = 0;  ///< the precomputation's peak structure (freed after)

  std::size_t bytes() const {
    std::size_t b = 0;
    for (const auto& v : diffuse) b += v.bytes();
    for (const auto& vs : single)
      for (const auto& v : vs) b += v.bytes();
    return b;
  }
};

/// The samples' area-weighted irradiance transport vectors A_j E_j, compressed.
inline std::vector<SparseScalars> sampleTransports(const reference::SurfaceSamples& samples,
                                                   const scene::RayCaster& caster,
                                                   const PrtSettings& s,
                                                   const util::ParallelFor& parallelFor,
                                                   const util::Progress& progress) {
  std::vector<SparseScalars> out(samples.size());
  std::atomic<std::size_t> done{0};
  parallelFor(samples.size(), [&](std::size_t begin, std::size_t end) {
    std::vector<float> dense;
    for (std::size_t i = begin; i < end; ++i) {
      irradianceTransport(samples.position[i], samples.normal[i], samples.faceNormal[i], caster,
                          s.transport, dense);
      for (float& e : dense) e *= float(samples.area[i]);
      out[i] = compress(dense, s.transport.size, s.sampleTerms);
    }
    if (progress) progress(double(done += end - begin) / double(samples.size()));
  });
  return out;
}

/// The near field of the samples (reference/near_field.hpp), its radius from the spacing they
/// were placed at: a mesh with more triangles than the budget has a sample on each, closer than the
/// coarsened `spacing` says.
inline reference::NearField nearField(const reference::SurfaceSamples& samples, double spacing) {
  double area = 0;
  for (double a : samples.area) area += a;
  const double placed = std::sqrt(area / double(std::max<std::size_t>(1, samples.size())));
  return reference::NearField(samples.position,
                              std::vector<glm::dvec3>(samples.size(), glm::dvec3(0)), samples.area,
                              std::min(spacing, placed));
}

/// The per-vertex vectors from the diffusion `profile`; `near` (optional) integrates the samples
/// near each vertex as a disc (reference/near_field.hpp) where the spacing does not resolve Rd;
/// `singleTerm` (built with no lights) follows light inside for the single-scattering vectors.
inline void vertexTransports(const std::vector<glm::dvec3>& vertices,
                             const std::vector<glm::vec3>& normals,
                             const TransportHierarchy& hierarchy,
                             const optics::Profile<double>& profile,
                             const reference::NearField* near,
                             const reference::SingleScattering* singleTerm,
                             const scene::RayCaster& caster, const PrtSettings& s, PrtModel& model,
                             const util::ParallelFor& parallelFor, const util::Progress& progress) {
  const int size = s.transport.size;
  const std::size_t texels = std::size_t(6) * size * size;
  const std::size_t keep = s.vertexTerms == 0 ? texels : s.vertexTerms;
  const bool folded = model.phase.terms() == 1;  // isotropic: one diffuse vector
  const float toExit = float(profile.exitScale / optics::kPi),
              toOutside = float(1 / (s.transport.eta * s.transport.eta));
  model.diffuse.assign(vertices.size(), {});
  model.single.assign(singleTerm && !folded ? vertices.size() : 0, {});
  const double reach = s.reachFraction < 1 ? profile.largestRadiusHolding(s.reachFraction)
                                            : std::numeric_limits<double>::infinity();
  std::atomic<std::size_t> done{0};
  parallelFor(vertices.size(), [&](std::size_t begin, std::size_t end) {
    std::vector<glm::vec3> acc(texels);
    std::vector<std::vector<glm::vec3>> single;
    for (std::size_t v = begin; v < end; ++v) {
      std::fill(acc.begin(), acc.end(), glm::vec3(0));
      hierarchy.gather(
          vertices[v], [&](double r) { return glm::dvec3(profile.rd(r)); }, acc, reach);
      if (near)
        near->forEachNear(vertices[v], profile, [&](std::uint32_t i, const glm::dvec3& c) {
          hierarchy.addSample(i, glm::vec3(c), acc);
        });
      for (auto& c : acc) c *= toExit;
      if (singleTerm) {
        const glm::dvec3 n(normals[v]);
        singleTransport(*singleTerm, model.phase, vertices[v], n, n, caster, s.singleSampling,
                        single);
        for (auto& k : single) {
          haarForwardCube(k, size);
          for (auto& c : k) c *= toOutside;
        }
        if (folded) {
          for (std::size_t i = 0; i < texels; ++i) acc[i] += single[0][i];
        } else {
          for (auto& k : single) model.single[v].push_back(quantize(keepLargest(k, size, keep)));
        }
      }
      model.diffuse[v] = quantize(keepLargest(acc, size, keep));
    }
    if (progress) progress(double(done += end - begin) / double(vertices.size()));
  });
}

}  // namespace lucent::prt
