#pragma once
/// @file translucent_shadow_map.hpp
/// @brief The local term of the hybrid method (Chang et al. 2008 Sec. 4.2, after
/// Dachsbacher & Stamminger 2003): the surface as the light sees it, stored on a plane normal to
/// the light (first hit and the power per unit plane area rho = E / |n_geom . axis|), filtered
/// around the projection of x_o with the ring filter (ring_filter.hpp) using 3-D distances, so thin
/// parts glow.
///
/// The map is orthographic along the light's direction (for a point light, the direction from the
/// light to the object's centre; E itself is the point light's exact irradiance with shadows).
/// Limits, stated: one depth layer per light (surface the map cannot see adds nothing locally; the
/// global term sees it), point lights close to the object are approximated by that one axis, and
/// environment lights have no light view (use tsis there). Grazing texels cap 1/|n . axis| at
/// kMaxObliquity.
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <variant>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "../reference/radial_table_sum.hpp"
#include "../scene/irradiance.hpp"
#include "../scene/mesh.hpp"
#include "../util/basis.hpp"
#include "../util/parallel.hpp"
#include "ring_filter.hpp"

namespace lucent::atlas {

inline constexpr double kMaxObliquity =
    20.0;  ///< cap of 1/|n.axis| (faces within 3 degrees of grazing)

/// A light view's frame: orthographic along `axis` (from the light into the object) over the
/// object's bounding sphere, texel (x, y) centred at centre + (-h + (x + 1/2) 2h / res) t + (...)
/// b.
struct LightViewFrame {
  glm::dvec3 centre{0}, axis{0, 0, -1}, t{1, 0, 0}, b{0, 1, 0};
  double halfExtent = 0;  ///< h
};

/// The frame for a point light (the axis from it to the bounds' centre) or a directional light;
/// throws for an environment light.
inline LightViewFrame lightViewFrame(const scene::Light& light, const scene::Bounds& bounds) {
  LightViewFrame f;
  f.centre = bounds.center();
  f.halfExtent = 0.5 * bounds.diagonal() * 1.001 + 1e-9;
  if (const auto* p = std::get_if<scene::PointLight>(&light)) {
    const glm::dvec3 d = f.centre - p->position;
    f.axis = glm::length(d) > 0 ? glm::normalize(d) : glm::dvec3(0, 0, -1);
  } else if (const auto* dl = std::get_if<scene::DirectionalLight>(&light)) {
    f.axis = -glm::normalize(dl->towardLight);
  } else {
    throw std::invalid_argument(
        "a translucent shadow map needs a point or directional light; "
        "environment lights have no light view (use --method tsis)");
  }
  util::orthonormalBasis(f.axis, f.t, f.b);
  return f;
}

class TranslucentShadowMap {
 public:
  /// @param light a point or directional light (throws for an environment light).
  TranslucentShadowMap(const scene::Light& light, const scene::TriangleMesh& mesh,
                       const std::vector<glm::vec3>& vertexNormals, const scene::RayCaster& caster,
                       const scene::IrradianceSettings& irr, int resolution,
                       const util::ParallelFor& parallelFor = util::serialFor)
      : mResolution(resolution) {
    if (resolution < 2)
      throw std::invalid_argument("translucent shadow map resolution must be >= 2");
    const LightViewFrame frame = lightViewFrame(light, mesh.bounds());
    mCenter = frame.centre, mAxis = frame.axis, mT = frame.t, mB = frame.b;
    const double radius = frame.halfExtent;
    mHalfExtent = radius;
    mTexel = 2 * radius / resolution;
    const std::size_t texels = std::size_t(resolution) * resolution;
    mTexels.assign(texels, MapTexel{});
    mValid.assign(texels, 0);
    const std::vector<scene::Light> one{light};
    parallelFor(std::size_t(resolution), [&](std::size_t begin, std::size_t end) {
      for (std::size_t y = begin; y < end; ++y)
        for (int x = 0; x < resolution; ++x) {
          const glm::dvec3 q = mCenter + (-radius + (x + 0.5) * mTexel) * mT +
                               (-radius + (double(y) + 0.5) * mTexel) * mB;
          const glm::dvec3 origin = q - 2 * radius * mAxis;
          const auto hit = caster.intersect(origin, mAxis, 0, 4 * radius);
          if (!hit) continue;
          const glm::dvec3 fn = glm::normalize(mesh.areaVector(hit->triangle));
          const glm::dvec3 n = scene::shadingNormal(
              mesh, vertexNormals, hit->triangle, glm::dvec3(1 - hit->u - hit->v, hit->u, hit->v));
          const glm::dvec3 x3 = origin + hit->t * mAxis;
          const glm::dvec3 e = scene::irradianceAt(x3, n, fn, one, caster, irr, y * resolution + x);
          const double obliquity =
              std::min(kMaxObliquity, 1.0 / std::max(std::abs(glm::dot(fn, mAxis)), 1e-12));
          const std::size_t i = y * resolution + std::size_t(x);
          mTexels[i] = {glm::vec3(x3), glm::vec3(e * obliquity)};
          mValid[i] = 1;
        }
    });
  }

  /// Calls visit(texel, k, share) for each ring-filter tap around x_o's projection that lands on a
  /// covered texel: k the tap's stratum (0 = the centre), share its part of the stratum (1/C on a
  /// ring). `turn` rotates the rings (radians): a turn per shaded point trades the pattern's fixed
  /// spokes for noise.
  template <class Visit>
  void forEachTap(const glm::dvec3& xo, const RingFilter& ring, Visit&& visit,
                  double turn = 0) const {
    requireTaps(ring);
    const glm::dvec2 p = project(xo);
    const double ct = std::cos(turn), st = std::sin(turn);
    if (const std::size_t i = coveredTexel(p); i != kUncovered) visit(i, std::size_t(0), 1.0);
    for (std::size_t j = 0; j < ring.tapOffset.size(); ++j) {
      const glm::dvec2 o = ring.tapOffset[j];
      const std::size_t i = coveredTexel(p + glm::dvec2(ct * o.x - st * o.y, st * o.x + ct * o.y));
      if (i != kUncovered) visit(i, ring.tapStratum(j), 1.0 / ring.perRing);
    }
  }

  /// int rho f(|x - x_o|) dA over the map around x_o's projection, by the ring filter (per
  /// channel).
  /// @param profile callable double -> dvec3, the filtered profile f.
  template <class Profile>
  glm::dvec3 filter(const glm::dvec3& xo, const RingFilter& ring, const Profile& profile) const {
    glm::dvec3 sum(0);
    forEachTap(xo, ring, [&](std::size_t i, std::size_t k, double share) {
      const double d = glm::length(position(i) - xo);
      if (k == 0) {
        sum += centreEstimate(ring, i, d);
        return;
      }
      sum += ring.tapEstimate(k, share, density(i) * profile(d));
    });
    return sum;
  }

  /// filter() for a profile held in a radial table, as the hybrid's is: the covered ring taps are
  /// gathered into float arrays (position, rho times the tap's ratio factor) and summed by the
  /// vectorised table kernel that TSIS uses (radial_table_sum.hpp). Equal to filter() with that
  /// table to float rounding; no trigonometry or division per tap.
  glm::dvec3 filterTable(const glm::dvec3& xo, const RingFilter& ring,
                         const reference::PlanarRadialTable& table) const {
    requireTaps(ring);
    thread_local reference::GatheredSamples taps;
    taps.fit(ring.tapOffset.size());
    const glm::dvec2 p = project(xo);
    glm::dvec3 sum(0);
    if (const std::size_t i = coveredTexel(p); i != kUncovered)
      sum += centreEstimate(ring, i, glm::length(position(i) - xo));
    // The taps in texel units: no division or floor per tap (the loop is a gather, its arithmetic
    // must be cheap), in double: a tap on a texel edge differs from coveredTexel only by rounding.
    const double inv = 1 / mTexel, ox = (p.x + mHalfExtent) * inv, oy = (p.y + mHalfExtent) * inv;
    const double size = double(mResolution);
    std::size_t n = 0;
    for (std::size_t j = 0; j < ring.tapOffset.size(); ++j) {
      const double fx = ox + ring.tapOffset[j].x * inv, fy = oy + ring.tapOffset[j].y * inv;
      if (!(fx >= 0 && fy >= 0 && fx < size && fy < size)) continue;
      const std::size_t i = std::size_t(fy) * std::size_t(mResolution) + std::size_t(fx);
      if (!mValid[i]) continue;
      const MapTexel& t = mTexels[i];
      taps.set(n++, t.position, glm::vec3(ring.tapFactor[j]) * t.density);
    }
    double ring3[3];
    reference::radialTableSum(taps.view(n), table, float(xo.x), float(xo.y), float(xo.z), ring3);
    return sum + glm::dvec3(ring3[0], ring3[1], ring3[2]);
  }

  ///@{ A texel: whether the surface covers it, its first hit (mm), rho (power per unit map area).
  std::size_t texelCount() const { return mValid.size(); }
  bool covered(std::size_t texel) const { return mValid[texel] != 0; }
  glm::dvec3 position(std::size_t texel) const { return glm::dvec3(mTexels[texel].position); }
  glm::dvec3 density(std::size_t texel) const { return glm::dvec3(mTexels[texel].density); }
  ///@}

  /// The power the map holds (sum of rho times the texel area): what the light puts into the
  /// surface it sees.
  glm::dvec3 totalPower() const {
    glm::dvec3 s(0);
    for (const MapTexel& t : mTexels) s += glm::dvec3(t.density) * (mTexel * mTexel);
    return s;
  }
  int resolution() const { return mResolution; }
  double texelSize() const { return mTexel; }

 private:
  static constexpr std::size_t kUncovered = std::numeric_limits<std::size_t>::max();

  static void requireTaps(const RingFilter& ring) {
    if (!ring.tapsPlaced())
      throw std::logic_error("ring filter without its taps: build it with makeRingFilter");
  }
  /// x_o's projection on the map's plane (mm along t and b from its centre).
  glm::dvec2 project(const glm::dvec3& xo) const {
    const glm::dvec3 rel = xo - mCenter;
    return {glm::dot(rel, mT), glm::dot(rel, mB)};
  }
  /// The texel holding plane point p, or kUncovered when p is off the map or on no surface.
  std::size_t coveredTexel(const glm::dvec2& p) const {
    const int x = int(std::floor((p.x + mHalfExtent) / mTexel));
    const int y = int(std::floor((p.y + mHalfExtent) / mTexel));
    if (x < 0 || y < 0 || x >= mResolution || y >= mResolution) return kUncovered;
    const std::size_t i = std::size_t(y) * std::size_t(mResolution) + std::size_t(x);
    return mValid[i] ? i : kUncovered;
  }
  /// The centre tap: its disc, exact for a flat disc d off its plane (ring_filter.hpp).
  glm::dvec3 centreEstimate(const RingFilter& ring, std::size_t i, double d) const {
    return ring.mass[0] * density(i) * ring.centreTransfer(d);
  }

  int mResolution;
  glm::dvec3 mCenter{0}, mAxis{0, 0, -1}, mT{1, 0, 0}, mB{0, 1, 0};
  double mHalfExtent = 0, mTexel = 0;
  /// A texel's first hit and rho side by side: a tap reads one cache line, not two.
  struct MapTexel {
    glm::vec3 position{0}, density{0};
  };
  std::vector<MapTexel> mTexels;
  std::vector<std::uint8_t> mValid;
};

}  // namespace lucent::atlas
