#pragma once
/// @file single_scattering.hpp
/// @brief The single-scattering term of a homogeneous object behind a smooth dielectric boundary
/// (Jensen, Marschner, Levoy, Hanrahan 2001, Eq. 6's L^(1); DESIGN.md): light crosses the boundary,
/// reaches a point x on the viewer's path unscattered, scatters once by the HG phase function and
/// leaves through x_o:
///   L(x_o, w_o) = Ft(eta, w_o) / eta^2 int_0^d e^{-sigma_t t} sigma_s int p L_in(x, w') dw' dt.
/// - The viewer's path is the refracted outgoing ray and its reflections inside the boundary
/// (weight
///   Fr at each, while it carries 1e-4 of the light; `Path::Refracted`), or the negative normal
///   alone
///   (`Path::NegativeNormal`), the view-independent path of Wang, Tran, Luebke 2005 (Sec. 3, Fig.
///   2b) that PRT precomputes along.
/// - An environment: L_in is gathered over directions w' inside, each followed through the
///   boundary's reflections (Fr) to where it refracts out (Ft, eta^2 L_env of the refracted
///   direction): exact but for the quadrature.
/// - A point or directional light: Jensen 2001's incident path, the straight line from x towards
///   the light meeting the surface at x_i after s_i, refracted through a locally flat boundary,
///   s_i' = s_i |w_i.n_i| / sqrt(1 - (1/eta)^2 (1 - |w_i.n_i|^2)), with the flux density across the
///   refracted beam Ft E cos(theta_i) / cos(theta_i') and a point light's falloff from its paraxial
///   image rest + s_i'/eta away (exact at eta = 1; reflections inside are left out: reaching a
///   delta light through a refracting boundary exactly needs manifold walks).
/// - Depths t are N deterministic stratified distances per distinct channel coefficient,
///   t = -ln(1 - Lambda xi) / sigma_t, Lambda = 1 - e^{-sigma_t d} (Wang et al. 2005, with xi =
///   (k - 1/2) / N), the channels' strategies combined by the balance heuristic.
/// Stated limit: a path that leaves the object and enters it again (a non-convex object) is
/// followed only to where it leaves.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <variant>
#include <vector>

#include <glm/geometric.hpp>

#include "../optics/fresnel.hpp"
#include "../optics/phase_hg.hpp"
#include "../scene/light.hpp"
#include "../scene/mesh.hpp"
#include "../scene/ray_caster.hpp"

namespace lucent::reference {

/// A homogeneous medium for single scattering: sigma_s and sigma_t = sigma_a + sigma_s per channel,
/// mm^-1 (not reduced), the HG asymmetry g and the relative index of refraction eta.
struct HomogeneousScattering {
  glm::dvec3 sigmaS{0}, sigmaT{0};
  double g = 0, eta = 1;
};

struct SingleScatteringSettings {
  enum class Path { Refracted, NegativeNormal };
  Path path = Path::Refracted;
  int depthSamples = 16;      ///< N per distinct channel coefficient
  int environmentStrata = 8;  ///< an environment: strata x 2 strata directions over the sphere
  double rayEpsilon = 1e-4;   ///< mm, off the surface for rays
};

/// One depth t on the viewer's path and its per-channel weight e^{-sigma_t t} / (pdf sum).
struct DepthSample {
  double t = 0;
  glm::dvec3 weight{0};
};

/// The depth samples of int_0^d e^{-sigma_t t} f(t) dt: N stratified distances from each distinct
/// channel's exponential on [0, d], combined by the balance heuristic, so a channel is sampled
/// where its own attenuation lets light through.
/// `rates` the strategies' coefficients (empty: each distinct channel's).
inline std::vector<DepthSample> depthSamples(const glm::dvec3& sigmaT, double d, int n,
                                             std::vector<double> rates = {}) {
  if (rates.empty())
    for (int c = 0; c < 3; ++c)
      if (std::find(rates.begin(), rates.end(), sigmaT[c]) == rates.end())
        rates.push_back(sigmaT[c]);
  // pdf of one strategy on [0, d]: sigma e^{-sigma t} / Lambda, uniform 1/d where sigma d vanishes.
  auto pdf = [d](double sigma, double t) {
    const double lambda = -std::expm1(-sigma * d);
    return lambda > 1e-12 ? sigma * std::exp(-sigma * t) / lambda : 1 / d;
  };
  std::vector<DepthSample> out;
  if (!(d > 0) || !std::isfinite(d) || n < 1) return out;
  for (double sigma : rates) {
    const double lambda = -std::expm1(-sigma * d);
    for (int k = 0; k < n; ++k) {
      const double xi = (k + 0.5) / n;
      const double t = lambda > 1e-12 ? -std::log1p(-lambda * xi) / sigma : xi * d;
      double pdfSum = 0;
      for (double other : rates) pdfSum += n * pdf(other, t);
      DepthSample s;
      s.t = std::min(t, d);
      for (int c = 0; c < 3; ++c) s.weight[c] = std::exp(-sigmaT[c] * s.t) / pdfSum;
      out.push_back(s);
    }
  }
  return out;
}

class SingleScattering {
 public:
  using Path = SingleScatteringSettings::Path;

  /// @param vertexNormals the mesh's smooth normals (the boundary's orientation where light
  /// enters).
  SingleScattering(const HomogeneousScattering& medium, const std::vector<scene::Light>& lights,
                   const scene::TriangleMesh& mesh, const std::vector<glm::vec3>& vertexNormals,
                   const scene::RayCaster& caster, const SingleScatteringSettings& settings)
      : mMedium(medium),
        mLights(lights),
        mMesh(mesh),
        mNormals(vertexNormals),
        mCaster(caster),
        mSettings(settings) {}

  /// Radiance leaving x_o towards `toEye` (unit) through the boundary of shading normal `normal`
  /// and geometric normal `faceNormal` (both unit, outward).
  glm::dvec3 radiance(const glm::dvec3& xo, const glm::dvec3& normal, const glm::dvec3& faceNormal,
                      const glm::dvec3& toEye) const {
    const double cosOut = glm::dot(normal, toEye);
    if (!(cosOut > 0)) return glm::dvec3(0);
    const double eta = mMedium.eta;
    // The direction the scattered light travels inside to leave towards the eye, reversed.
    const glm::dvec3 refracted = glm::refract(-toEye, normal, 1.0 / eta);
    if (glm::dot(refracted, refracted) == 0) return glm::dvec3(0);
    const bool normalPath = mSettings.path == Path::NegativeNormal;
    glm::dvec3 origin = xo - faceNormal * mSettings.rayEpsilon;
    glm::dvec3 dir = normalPath ? -normal : refracted;
    glm::dvec3 carried(1), sum(0);  // Fr products and e^{-sigma_t T} of the segments before
    for (int segment = 0; segment < kMaxReflections; ++segment) {
      const auto wall = mCaster.intersect(origin, dir, 0, std::numeric_limits<double>::infinity());
      if (!wall) break;  // an open surface: no inside to scatter in
      // Light scattered towards the eye travels against the view path (Wang et al.: along -normal's
      // reverse, with the phase still taken towards the refracted view ray).
      const glm::dvec3 out = normalPath ? -refracted : -dir;
      for (const DepthSample& s : depthSamples(mMedium.sigmaT, wall->t, mSettings.depthSamples))
        sum += carried * s.weight * inScattered(origin + dir * s.t, out);
      if (normalPath) break;
      // The view path reflects where it meets the boundary again.
      const Bounce b = reflectInside(origin, dir, *wall);
      for (int c = 0; c < 3; ++c)
        carried[c] *= b.reflectance * std::exp(-mMedium.sigmaT[c] * wall->t);
      if (std::max(carried.x, std::max(carried.y, carried.z)) < kNegligible) break;
      origin = b.origin, dir = b.direction;
    }
    return sum * (optics::fresnelTransmittance(cosOut, eta) / (eta * eta));
  }

  /// Follows the ray from x along w (inside) through the boundary's reflections; at each place it
  /// can leave unblocked, calls exit(direction outside, e^{-sigma_t s} Ft times the reflectances
  /// before): the share of light arriving from that direction outside that reaches x along -w.
  template <class Exit>
  void forEachExit(glm::dvec3 x, glm::dvec3 w, Exit&& exit) const {
    glm::dvec3 carried(1);
    for (int bounce = 0; bounce < kMaxReflections; ++bounce) {
      const auto wall = mCaster.intersect(x, w, 0, std::numeric_limits<double>::infinity());
      if (!wall) break;
      for (int c = 0; c < 3; ++c) carried[c] *= std::exp(-mMedium.sigmaT[c] * wall->t);
      const Bounce b = reflectInside(x, w, *wall);
      if (b.reflectance < 1 &&
          !mCaster.occluded(b.exitPoint, b.outside, 0, std::numeric_limits<double>::infinity()))
        exit(b.outside, carried * (1 - b.reflectance));
      carried *= b.reflectance;
      if (std::max(carried.x, std::max(carried.y, carried.z)) < kNegligible) break;
      x = b.origin, w = b.direction;
    }
  }

  const HomogeneousScattering& medium() const { return mMedium; }

  /// Jensen 2001's incident path from x towards a light `towardLight` (unit) up to lightDistance:
  /// where the straight line leaves, the refracted length s_i' and its attenuation, the flux
  /// density across the refracted beam per unit irradiance (Ft cos(theta_i) / cos(theta_i')), the
  /// light's direction of travel inside; none when the line meets no boundary facing the light or
  /// the light is blocked outside.
  struct StraightEntry {
    glm::dvec3 attenuation{0}, travel{0};
    double transmitted = 0, refractedLength = 0, rest = 0;
  };
  std::optional<StraightEntry> enterStraight(const glm::dvec3& x, const glm::dvec3& towardLight,
                                             double lightDistance) const {
    const auto hit = mCaster.intersect(x, towardLight, 0, lightDistance);
    if (!hit) return std::nullopt;
    const std::uint32_t tri = hit->triangle;
    const glm::dvec3 faceNormal = glm::normalize(mMesh.areaVector(tri));
    const glm::dvec3 n =
        scene::shadingNormal(mMesh, mNormals, tri, {1 - hit->u - hit->v, hit->u, hit->v});
    const double cosI = std::abs(glm::dot(n, towardLight));
    if (!(cosI > 0) || glm::dot(faceNormal, towardLight) <= 0) return std::nullopt;
    StraightEntry e;
    e.rest = lightDistance - hit->t;
    const glm::dvec3 xi = x + towardLight * hit->t + faceNormal * mSettings.rayEpsilon;
    if (mCaster.occluded(xi, towardLight, 0, e.rest)) return std::nullopt;
    const double eta = mMedium.eta;
    const double cosRefracted = std::sqrt(std::max(0.0, 1 - (1 - cosI * cosI) / (eta * eta)));
    e.refractedLength = hit->t * cosI / cosRefracted;  // Jensen 2001's s_i'
    e.travel = glm::refract(-towardLight, n, 1.0 / eta);
    e.transmitted = optics::fresnelTransmittance(cosI, eta) * cosI / cosRefracted;
    for (int c = 0; c < 3; ++c) e.attenuation[c] = std::exp(-mMedium.sigmaT[c] * e.refractedLength);
    return e;
  }

 private:
  static constexpr int kMaxReflections = 16;
  static constexpr double kNegligible = 1e-4;

  /// Where a ray inside meets the boundary: the share reflected back in (Fr, or 1 beyond the
  /// critical angle), the reflected ray, and the refracted direction outside (zero under total
  /// internal reflection) with its cosine.
  struct Bounce {
    double reflectance = 1;
    glm::dvec3 origin{0}, direction{0}, outside{0};
    glm::dvec3 exitPoint{0};
    double cosOutside = 0;
  };
  Bounce reflectInside(const glm::dvec3& from, const glm::dvec3& dir,
                       const scene::RayHit& hit) const {
    const glm::dvec3 face = glm::normalize(mMesh.areaVector(hit.triangle));
    glm::dvec3 n =
        scene::shadingNormal(mMesh, mNormals, hit.triangle, {1 - hit.u - hit.v, hit.u, hit.v});
    if (glm::dot(n, dir) <= 0) n = face;  // a shading normal turned away: the face's
    const glm::dvec3 at = from + dir * hit.t;
    Bounce b;
    b.origin = at - face * mSettings.rayEpsilon;
    b.exitPoint = at + face * mSettings.rayEpsilon;
    b.direction = glm::reflect(dir, n);
    b.outside = glm::refract(dir, -n, mMedium.eta);
    if (glm::dot(b.outside, b.outside) > 0) {
      b.cosOutside = glm::dot(b.outside, n);
      b.reflectance = optics::fresnelReflectance(b.cosOutside, mMedium.eta);
    }
    return b;
  }

  /// sigma_s int p L_in: the light scattered at x into direction `out` (inside, unit).
  glm::dvec3 inScattered(const glm::dvec3& x, const glm::dvec3& out) const {
    glm::dvec3 sum(0);
    for (const scene::Light& light : mLights) {
      if (const auto* p = std::get_if<scene::PointLight>(&light)) {
        const glm::dvec3 d = p->position - x;
        const double dist = glm::length(d);
        if (dist > 0) sum += throughBoundary(x, d / dist, dist, out, p->intensity, true);
      } else if (const auto* dl = std::get_if<scene::DirectionalLight>(&light)) {
        sum += throughBoundary(x, glm::normalize(dl->towardLight),
                               std::numeric_limits<double>::infinity(), out, dl->irradiance, false);
      } else if (const auto* env = std::get_if<scene::EnvironmentLight>(&light)) {
        sum += fromEnvironment(x, out, *env);
      }
    }
    return sum * mMedium.sigmaS;
  }

  /// int p L_in dw' over stratified directions w' inside (uniform in cos theta and phi), each
  /// followed through the boundary's reflections to where it leaves; L_in = eta^2 Ft L_env there.
  glm::dvec3 fromEnvironment(const glm::dvec3& x, const glm::dvec3& out,
                             const scene::EnvironmentLight& env) const {
    const int k = std::max(1, mSettings.environmentStrata);
    const double dOmega = 4 * optics::kPi / (2.0 * k * k);
    const double eta2 = mMedium.eta * mMedium.eta;
    glm::dvec3 sum(0);
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < 2 * k; ++j) {
        const double z = 1 - 2 * (i + 0.5) / k, r = std::sqrt(std::max(0.0, 1 - z * z));
        const double phi = optics::kPi * (j + 0.5) / k;
        const glm::dvec3 w(r * std::cos(phi), r * std::sin(phi), z);
        const double phase = optics::phaseHG(glm::dot(-w, out), mMedium.g);
        sum += phase * dOmega * eta2 * environmentAlong(x, w, env);
      }
    return sum;
  }

  /// The environment's light arriving at x from direction w (inside): e^{-sigma_t s} Ft L_env at
  /// each exit, times the reflectances of the walls before it.
  glm::dvec3 environmentAlong(const glm::dvec3& x, const glm::dvec3& w,
                              const scene::EnvironmentLight& env) const {
    glm::dvec3 sum(0);
    forEachExit(x, w, [&](const glm::dvec3& outside, const glm::dvec3& weight) {
      sum += weight * env.lookup(outside);
    });
    return sum;
  }

  /// p e^{-sigma_t s_i'} Ft cos/cos' E for light arriving from `towardLight` with irradiance
  /// `e` (an intensity over distance^2 when `inverseSquare`) at x; 0 when the boundary is not
  /// reached or the light is blocked outside.
  glm::dvec3 throughBoundary(const glm::dvec3& x, const glm::dvec3& towardLight,
                             double lightDistance, const glm::dvec3& out, const glm::dvec3& e,
                             bool inverseSquare) const {
    const auto entry = enterStraight(x, towardLight, lightDistance);
    if (!entry) return glm::dvec3(0);
    const double phase = optics::phaseHG(glm::dot(entry->travel, out), mMedium.g);
    // A point light's beam spreads from a virtual source rest + s_i'/eta away (paraxially, through
    // a flat boundary; the straight distance to the light at eta = 1).
    const double spread = entry->rest + entry->refractedLength / mMedium.eta;
    return e * entry->attenuation *
           (entry->transmitted * phase / (inverseSquare ? spread * spread : 1.0));
  }

  HomogeneousScattering mMedium;
  const std::vector<scene::Light>& mLights;
  const scene::TriangleMesh& mMesh;
  const std::vector<glm::vec3>& mNormals;
  const scene::RayCaster& mCaster;
  SingleScatteringSettings mSettings;
};

}  // namespace lucent::reference
