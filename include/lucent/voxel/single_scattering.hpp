#pragma once
/// @file single_scattering.hpp
/// @brief Single scattering through the voxel media, physically normalised: the radiance
///   L(x_o, w_o) = Ft(eta, w_o) / eta^2 int_0^inf sigma_s(x_t) p(w_l . w_t') e^{-tau_view(t)}
///                 sum_lights E_l Ft(eta, w_l . n_l) e^{-tau_light(x_t)} dt
/// along the refracted view ray x_t = x_o + t w_t (w_t' = -w_t the direction the light leaves in),
/// with tau to the light by the same exact DDA over the same MediaGrid as the optical-thickness
/// LUT (Jensen, Marschner, Levoy, Hanrahan 2001, Eq. 6's single-scattering term; Mochida et al.
/// 2016 say their Rd = e^{-tau} holds where this term dominates).
///
/// The integral, per channel, by two deterministic stratified strategies combined with the
/// balance heuristic: N optical depths tau_k = -ln(1 - Lambda (k + 1/2) / N), Lambda =
/// 1 - e^{-tau_max} (pdf sigma_t e^{-tau} / Lambda: the s = -ln(1 - Lambda xi) / sigma_t of Wang,
/// Tran, Luebke 2005, here through heterogeneous media), which follows the view's attenuation; and
/// N points uniform in the length through media, which keeps the far side sampled where the light
/// arrives (a back-lit thick object, where e^{-tau_view} e^{-tau_light} is flat along the ray).
/// Stated limits: the light's path is the straight line (exact at eta = 1, where the path tracer
/// checks it; Jensen 2001's approximation otherwise) with one Fresnel transmission where it first
/// meets the surface; the view ray is refracted once at x_o and then runs straight through the
/// grid.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <variant>
#include <vector>

#include <glm/geometric.hpp>

#include "../optics/fresnel.hpp"
#include "../optics/phase_hg.hpp"
#include "../scene/light.hpp"
#include "../scene/mesh.hpp"
#include "../scene/ray_caster.hpp"
#include "grid_traversal.hpp"

namespace lucent::voxel {

/// A medium's coefficients, mm^-1 at density 1: sigma_s (not reduced) and sigma_t = sigma_a +
/// sigma_s.
struct ScatteringCoefficients {
  glm::dvec3 sigmaS{0}, sigmaT{0};
};

/// A piece of a ray inside one voxel of a medium, with the voxel's coefficients at its density.
struct RaySegment {
  double t0 = 0, t1 = 0;
  ScatteringCoefficients c;
};

/// The segments of o + t d, t in [0, length], that lie in a medium (`media[m - 1]` for medium m).
inline std::vector<RaySegment> mediaAlong(const MediaGrid& grid,
                                          const std::vector<ScatteringCoefficients>& media,
                                          const glm::dvec3& o, const glm::dvec3& d, double length) {
  std::vector<RaySegment> out;
  traverse(grid, o, o + d * length, [&](const glm::ivec3& v, double t0, double t1) {
    const std::size_t i = grid.index(v);
    const std::uint8_t m = grid.medium[i];
    if (m == kNoMedium || m > media.size()) return;
    const double rho = grid.densityAt(i);
    out.push_back(
        {t0 * length, t1 * length, {media[m - 1u].sigmaS * rho, media[m - 1u].sigmaT * rho}});
  });
  return out;
}

/// tau per channel along a -> b.
inline glm::dvec3 opticalDepth(const MediaGrid& grid,
                               const std::vector<ScatteringCoefficients>& media,
                               const glm::dvec3& a, const glm::dvec3& b) {
  glm::dvec3 tau(0);
  const double length = glm::length(b - a);
  if (!(length > 0)) return tau;
  for (const auto& s : mediaAlong(grid, media, a, (b - a) / length, length))
    tau += s.c.sigmaT * (s.t1 - s.t0);
  return tau;
}

class SingleScatteringEstimator {
 public:
  /// @param media per grid medium 1..; @param mesh, caster the object's surface (for the Fresnel
  /// term where the light enters); @param samples N depths per channel.
  SingleScatteringEstimator(const MediaGrid& grid, std::vector<ScatteringCoefficients> media,
                            const std::vector<scene::Light>& lights,
                            const scene::TriangleMesh& mesh, const scene::RayCaster& caster,
                            double eta, double g, int samples)
      : mGrid(grid),
        mMedia(std::move(media)),
        mLights(lights),
        mMesh(mesh),
        mCaster(caster),
        mEta(eta),
        mG(g),
        mSamples(samples),
        mReach(glm::length(grid.upperCorner() - grid.lowerCorner())) {}

  /// Radiance leaving x_o towards `toEye` (unit) through a surface of outward `normal`.
  glm::dvec3 radiance(const glm::dvec3& xo, const glm::dvec3& toEye,
                      const glm::dvec3& normal) const {
    const double cosOut = glm::dot(normal, toEye);
    if (!(cosOut > 0)) return glm::dvec3(0);
    const glm::dvec3 inward = glm::refract(-toEye, normal, 1.0 / mEta);
    const std::vector<RaySegment> segments = mediaAlong(mGrid, mMedia, xo, inward, mReach);
    glm::dvec3 l(0);
    for (int c = 0; c < 3; ++c) l[c] = channel(segments, xo, inward, c);
    // Radiance leaving a medium of index eta falls by 1/eta^2 (its solid angle widens), as the path
    // tracer's camera rays carry it (dielectric_interface.hpp).
    return l * (optics::fresnelTransmittance(cosOut, mEta) / (mEta * mEta));
  }

 private:
  /// int sigma_s e^{-tau} L_in dt of one channel: N stratified samples by optical depth and N
  /// uniform in the length through media, combined by the balance heuristic.
  double channel(const std::vector<RaySegment>& segments, const glm::dvec3& xo,
                 const glm::dvec3& inward, int c) const {
    // Optical depth and media length where each segment starts.
    std::vector<double> depth, length;
    double tauMax = 0, lengthMax = 0;
    for (const auto& s : segments) {
      depth.push_back(tauMax), length.push_back(lengthMax);
      tauMax += s.c.sigmaT[c] * (s.t1 - s.t0), lengthMax += s.t1 - s.t0;
    }
    const double lambda = -std::expm1(-tauMax);  // 1 - e^{-tau_max}, exact for tiny tau
    if (!(lambda > 0) || !(lengthMax > 0)) return 0;
    auto at = [&](std::size_t i, double t, double tau) {
      const RaySegment& s = segments[i];
      if (!(s.c.sigmaT[c] > 0)) return 0.0;
      const double pdf = mSamples * (s.c.sigmaT[c] * std::exp(-tau) / lambda + 1 / lengthMax);
      return s.c.sigmaS[c] * std::exp(-tau) * incoming(xo + inward * t, -inward, c) / pdf;
    };
    auto last = [](const std::vector<double>& starts, double v) {
      return std::size_t(std::upper_bound(starts.begin(), starts.end(), v) - starts.begin()) - 1;
    };
    double sum = 0;
    for (int k = 0; k < mSamples; ++k) {
      const double u = (k + 0.5) / mSamples;
      const double tau = -std::log1p(-lambda * u);  // by optical depth
      std::size_t i = last(depth, tau);
      if (segments[i].c.sigmaT[c] > 0)
        sum += at(i, segments[i].t0 + (tau - depth[i]) / segments[i].c.sigmaT[c], tau);
      const double l = u * lengthMax;  // uniform in length
      i = last(length, l);
      sum += at(i, segments[i].t0 + (l - length[i]),
                depth[i] + segments[i].c.sigmaT[c] * (l - length[i]));
    }
    return sum;
  }

  /// sum over lights of p E Ft e^{-tau_light} at x, scattered into `out` (channel c).
  double incoming(const glm::dvec3& x, const glm::dvec3& out, int c) const {
    double sum = 0;
    for (const auto& light : mLights) {
      glm::dvec3 toLight, end;
      double e = 0;
      if (const auto* p = std::get_if<scene::PointLight>(&light)) {
        const glm::dvec3 d = p->position - x;
        const double dist2 = glm::dot(d, d);
        if (!(dist2 > 0)) continue;
        toLight = d / std::sqrt(dist2), end = p->position, e = p->intensity[c] / dist2;
      } else if (const auto* dl = std::get_if<scene::DirectionalLight>(&light)) {
        toLight = glm::normalize(dl->towardLight), end = x + toLight * mReach;
        e = dl->irradiance[c];
      } else {
        continue;  // environment lights: not this estimator's (capabilities say so)
      }
      const double tau = opticalDepth(mGrid, mMedia, x, end)[c];
      sum += optics::phaseHG(glm::dot(-toLight, out), mG) * e * entryTransmittance(x, toLight) *
             std::exp(-tau);
    }
    return sum;
  }

  /// Ft where the straight line from x towards the light first meets the surface.
  double entryTransmittance(const glm::dvec3& x, const glm::dvec3& toLight) const {
    if (mEta == 1) return 1;
    const auto hit = mCaster.intersect(x, toLight, 0, mReach);
    if (!hit) return 1;
    const glm::dvec3 n = glm::normalize(mMesh.areaVector(hit->triangle));
    return optics::fresnelTransmittance(std::abs(glm::dot(n, toLight)), mEta);
  }

  const MediaGrid& mGrid;
  std::vector<ScatteringCoefficients> mMedia;
  const std::vector<scene::Light>& mLights;
  const scene::TriangleMesh& mMesh;
  const scene::RayCaster& mCaster;
  double mEta, mG;
  int mSamples;
  double mReach;  ///< the grid's diagonal: any ray inside it ends within
};

}  // namespace lucent::voxel
