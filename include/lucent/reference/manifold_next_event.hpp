#pragma once
/// @file manifold_next_event.hpp
/// @brief Manifold next-event estimation through one smooth refraction (Hanika, Droske, Fascione,
/// "Manifold Next Event Estimation", EGSR 2015), on the path tracer's own surface: flat triangles.
///
/// From a scattering vertex x inside a medium, a point or directional light outside can only be
/// reached through points y of the boundary where Snell's law bends the light towards x. On a flat
/// facet that point is exact: for a directional light it is where the reversed refracted direction
/// from x meets the plane; for a point light it minimises the optical path n_in |x - y| + n_out |y
/// - p| over the plane (Fermat), a strictly convex problem with one root, solved by safeguarded
/// Newton. Hanika's Newton walk over a smooth surface becomes a walk over facets: solve on the
/// facet the straight line x -> light crosses, and step across the edge the solution lies beyond
/// until it lies on its own facet. A curved surface makes more than one solution: the facets of a
/// tessellated curve overlap their beams, and a lens-like shape focuses light into caustics where
/// whole bands of facets bend light to the same point. So the search floods from the walk's end
/// across every facet within `gapSteps` edge steps of one with a solution, and sums them all.
/// Solutions in a band further away are missed (on a sphere, measured in the tests); a flood that
/// reaches its facet cap is counted.
///
/// The light's irradiance at x, per unit of its power, perpendicular to the path (the generalised
/// geometry term with the Fresnel transmittance): a beam from a directional light narrows or widens
/// by cos(theta_o) / cos(theta_i); from a point light at distance d_o from y, with d_i = |y - x|
/// and eta = n_out / n_in, the ray tube's two principal widths give
///   E_perp / I = Ft cos(theta_o) / ((d_o + eta d_i) (d_o cos(theta_i) + eta d_i cos^2(theta_o) /
///   cos(theta_i)))
/// (1 / d^2 at eta 1; the apparent depth d_o + d_i / n along the normal).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "../optics/fresnel.hpp"
#include "../scene/facet_adjacency.hpp"
#include "../scene/ray_caster.hpp"
#include "light_subpaths.hpp"
#include "participating_media.hpp"

namespace lucent::reference {

/// One way a delta light reaches x: through facet `triangle` at `point`.
struct RefractedConnection {
  std::uint32_t triangle = 0;
  glm::dvec3 point{0};
  glm::dvec3 towardsPoint{0};          ///< unit, x -> point: where the light arrives from at x
  double insideLength = 0;             ///< |point - x|
  glm::dvec3 towardsLight{0};          ///< unit, point -> light
  double outsideLength = 0;            ///< |light - point|; infinite for a directional light
  glm::dvec3 normalOut{0};             ///< the facet's unit normal on the light's side
  std::uint32_t inner = 0, outer = 0;  ///< the media on x's side and on the light's side
  double irradiancePerPower = 0;       ///< E_perp at x / the light's I or E (see the file comment)
  glm::dvec3 barycentric{0};           ///< of `point` in the triangle (all >= 0: on it)

  bool onFacet() const { return barycentric.x >= 0 && barycentric.y >= 0 && barycentric.z >= 0; }
};

/// A facet's plane, precomputed once: a corner, the unit normal (the side the winding faces) and
/// the dual edge vectors that give barycentric coordinates by two dot products.
struct FacetPlane {
  glm::dvec3 origin{0}, normal{0}, dual1{0}, dual2{0};
  bool valid = false;  ///< false for a degenerate (zero-area) triangle

  FacetPlane() = default;
  FacetPlane(const glm::dvec3& v0, const glm::dvec3& v1, const glm::dvec3& v2) : origin(v0) {
    const glm::dvec3 e1 = v1 - v0, e2 = v2 - v0, area = glm::cross(e1, e2);
    const double g11 = glm::dot(e1, e1), g12 = glm::dot(e1, e2), g22 = glm::dot(e2, e2);
    const double det = g11 * g22 - g12 * g12, areaLength = glm::length(area);
    valid = areaLength > 0 && det > 0;
    if (!valid) return;
    normal = area / areaLength;
    dual1 = (g22 * e1 - g12 * e2) / det;  // dot(p - v0, dual1) = the weight of v1
    dual2 = (g11 * e2 - g12 * e1) / det;
  }
  /// The weights of the corners v0, v1, v2 at p (in the plane); all >= 0 on the triangle.
  glm::dvec3 barycentric(const glm::dvec3& p) const {
    const double s = glm::dot(p - origin, dual1), t = glm::dot(p - origin, dual2);
    return {1 - s - t, s, t};
  }
};

namespace detail {

/// u in [lo, hi] where n_in u / sqrt(a^2 + u^2) = n_out (D - u) / sqrt(b^2 + (D - u)^2): Snell's
/// law in the plane of incidence, the stationary point of the optical path. The left side minus the
/// right rises monotonically from <= 0 at lo to >= 0 at hi (snellBracket); Newton from the paraxial
/// root (sin = tan), kept inside a shrinking bracket.
inline double snellRoot(double a, double b, double D, double nIn, double nOut, double lo,
                        double hi) {
  double u = std::clamp(D * nOut * a / (nOut * a + nIn * b), lo, hi);
  for (int i = 0; i < 100; ++i) {
    // Lengths stay far from overflow (mm; the scene is bounded), so no hypot.
    const double ra = std::sqrt(a * a + u * u), rb = std::sqrt(b * b + (D - u) * (D - u));
    const double fu = nIn * u / ra - nOut * (D - u) / rb;
    if (fu == 0) return u;
    (fu < 0 ? lo : hi) = u;
    const double slope = nIn * a * a / (ra * ra * ra) + nOut * b * b / (rb * rb * rb);
    const double next = u - fu / slope;
    // Converged first: u has just become a bracket end, so a step of rounding size is not inside.
    if (std::abs(next - u) <= 1e-14 * D) return next;
    u = next > lo && next < hi ? next : 0.5 * (lo + hi);
  }
  return u;
}

/// Where along [0, D] Snell's root lies: at u = D a / (a + b) the straight line crosses with equal
/// angles, so the left side of snellRoot's equation there is (n_in - n_out) sin: positive when x
/// is in the denser medium (the root lies nearer x's foot), negative otherwise.
inline std::pair<double, double> snellBracket(double a, double b, double D, double nIn,
                                              double nOut) {
  const double straight = D * a / (a + b);
  return nIn > nOut ? std::pair{0.0, straight} : std::pair{straight, D};
}

/// Where light from a point light refracts through the plane towards x (Fermat), setting the
/// outside half of `c`; false when the light is on x's side.
inline bool pointLightRefraction(const FacetPlane& plane, const glm::dvec3& x, double depth,
                                 const glm::dvec3& lightPosition, double nIn, double nOut,
                                 bool onFacetOnly, RefractedConnection& c, double& cosOut) {
  const double height = glm::dot(lightPosition - plane.origin, c.normalOut);
  if (!(height > 0)) return false;
  const glm::dvec3 xFoot = x + depth * c.normalOut,
                   lightFoot = lightPosition - height * c.normalOut;
  const double D = glm::length(lightFoot - xFoot);
  const auto [lo, hi] = detail::snellBracket(depth, height, D, nIn, nOut);
  const glm::dvec3 along = D > 0 ? (lightFoot - xFoot) / D : glm::dvec3(0);
  if (onFacetOnly) {
    // The root lies between the bracket's ends: outside one edge at both, it misses the facet.
    const glm::dvec3 a = plane.barycentric(xFoot + lo * along),
                     b = plane.barycentric(xFoot + hi * along);
    if ((a.x < 0 && b.x < 0) || (a.y < 0 && b.y < 0) || (a.z < 0 && b.z < 0)) return false;
  }
  const double u = D > 0 ? snellRoot(depth, height, D, nIn, nOut, lo, hi) : 0;
  c.point = xFoot + u * along;
  c.outsideLength = glm::length(lightPosition - c.point);
  c.towardsLight = (lightPosition - c.point) / c.outsideLength;
  cosOut = height / c.outsideLength;
  return true;
}

/// Where the reversed refracted ray of a directional light from x meets the plane; false when the
/// light is behind the plane or cannot pass into a lower index at its angle.
inline bool directionalRefraction(const glm::dvec3& x, double depth, const glm::dvec3& towards,
                                  double eta, RefractedConnection& c, double& cosOut) {
  c.towardsLight = glm::normalize(towards);
  cosOut = glm::dot(c.towardsLight, c.normalOut);
  if (!(cosOut > 0)) return false;
  const double sin2In = eta * eta * (1 - cosOut * cosOut);
  if (sin2In >= 1) return false;
  const double cosIn = std::sqrt(1 - sin2In);
  const glm::dvec3 refracted = -eta * c.towardsLight + (eta * cosOut - cosIn) * c.normalOut;
  c.point = x - (depth / cosIn) * refracted;
  c.outsideLength = std::numeric_limits<double>::infinity();
  return true;
}

}  // namespace detail

/// Where light from `light` refracts through the plane of triangle `t` (precomputed as `plane`)
/// towards x, if the plane separates them and light passes: the point (on the plane, not
/// necessarily on the triangle: see `barycentric`), the directions and media, without the geometry
/// term. With `onFacetOnly`, a point off the triangle may be reported as none (a cheaper test
/// first).
inline std::optional<RefractedConnection> refractionPoint(const MediumScene& scene, std::uint32_t t,
                                                          const FacetPlane& plane,
                                                          const glm::dvec3& x,
                                                          const LightEmitter& light,
                                                          bool onFacetOnly = false) {
  if (!plane.valid) return std::nullopt;
  const double side = glm::dot(x - plane.origin, plane.normal);  // < 0: x in the inside medium
  if (side == 0) return std::nullopt;
  RefractedConnection c;
  c.triangle = t;
  c.normalOut = side < 0 ? plane.normal : -plane.normal;
  c.inner = side < 0 ? scene.inside[t] : scene.outside[t];
  c.outer = side < 0 ? scene.outside[t] : scene.inside[t];
  const double nIn = scene.media[c.inner].eta, nOut = scene.media[c.outer].eta;
  if (nIn == nOut) return std::nullopt;  // a null interface: plain next-event estimation's
  const double depth = std::abs(side);
  double cosOut = 0;
  const bool passes =
      light.kind == LightEmitter::Kind::Point
          ? detail::pointLightRefraction(plane, x, depth, light.position, nIn, nOut, onFacetOnly, c,
                                         cosOut)
          : detail::directionalRefraction(x, depth, light.towards, nOut / nIn, c, cosOut);
  if (!passes) return std::nullopt;
  c.insideLength = glm::length(c.point - x);
  if (!(c.insideLength > 0)) return std::nullopt;
  c.towardsPoint = (c.point - x) / c.insideLength;
  c.barycentric = plane.barycentric(c.point);
  return c;
}

/// Sets c.irradiancePerPower, the generalised geometry term with Fresnel transmittance (see the
/// file comment); false when it is not a positive finite number.
inline bool setGeometryTerm(const MediumScene& scene, const LightEmitter& light,
                            RefractedConnection& c) {
  const double nIn = scene.media[c.inner].eta, nOut = scene.media[c.outer].eta, eta = nOut / nIn;
  const double cosIn = std::abs(glm::dot(c.towardsPoint, c.normalOut));
  const double cosOut = glm::dot(c.towardsLight, c.normalOut);
  const double transmitted = optics::fresnelTransmittance(cosOut, nIn / nOut);
  if (light.kind == LightEmitter::Kind::Point) {
    const double dO = c.outsideLength, dI = c.insideLength;
    c.irradiancePerPower = transmitted * cosOut /
                           ((dO + eta * dI) * (dO * cosIn + eta * dI * cosOut * cosOut / cosIn));
  } else {
    c.irradiancePerPower = transmitted * cosOut / cosIn;
  }
  return std::isfinite(c.irradiancePerPower) && c.irradiancePerPower > 0;
}

/// refractionPoint with its geometry term: the whole connection through the plane of `t`.
inline std::optional<RefractedConnection> refractThroughPlane(const MediumScene& scene,
                                                              std::uint32_t t,
                                                              const FacetPlane& plane,
                                                              const glm::dvec3& x,
                                                              const LightEmitter& light) {
  auto c = refractionPoint(scene, t, plane, x, light);
  if (!c || !setGeometryTerm(scene, light, *c)) return std::nullopt;
  return c;
}

inline FacetPlane facetPlane(const scene::TriangleMesh& mesh, std::uint32_t t) {
  const glm::uvec3 tri = mesh.triangles[t];
  return {glm::dvec3(mesh.positions[tri.x]), glm::dvec3(mesh.positions[tri.y]),
          glm::dvec3(mesh.positions[tri.z])};
}

/// refractThroughPlane for one triangle of the scene, its plane computed on the spot.
inline std::optional<RefractedConnection> refractThroughFacet(const MediumScene& scene,
                                                              std::uint32_t t, const glm::dvec3& x,
                                                              const LightEmitter& light) {
  return refractThroughPlane(scene, t, facetPlane(scene.mesh, t), x, light);
}

/// The search for every refraction point near the one the walk finds (see the file comment).
class ManifoldNextEvent {
 public:
  ManifoldNextEvent(const MediumScene& scene, const scene::RayCaster& caster, int gapSteps = 2,
                    int maxSteps = 256, std::size_t maxFlood = 1 << 14)
      : mScene(scene),
        mCaster(caster),
        mAdjacency(scene.mesh),
        mGapSteps(gapSteps),
        mMaxSteps(maxSteps),
        mMaxFlood(maxFlood) {
    mPlanes.reserve(scene.mesh.triangles.size());
    for (std::uint32_t t = 0; t < scene.mesh.triangles.size(); ++t)
      mPlanes.push_back(facetPlane(scene.mesh, t));
  }

  /// Appends to `out` the refraction points joining x to `light` (visibility not yet checked).
  void search(const glm::dvec3& x, const LightEmitter& light, double epsilon,
              std::vector<RefractedConnection>& out, ManifoldSearchStats& st) const {
    searchFrom(firstRefractingFacet(x, light, epsilon), x, light, out, st);
  }

  /// search, with the first facet between different indices on the straight line from x to the
  /// light already known (nullopt: there is none, so no refraction point either).
  void searchFrom(std::optional<std::uint32_t> seed, const glm::dvec3& x, const LightEmitter& light,
                  std::vector<RefractedConnection>& out, ManifoldSearchStats& st) const {
    ++st.searches;
    const std::size_t first = out.size();
    if (seed) collectAround(walk(*seed, x, light), x, light, out, st);
    const std::size_t found = out.size() - first;
    st.solutions += found;
    if (found == 0) ++st.noSolution;
    if (found > 1) ++st.multiple;
  }

 private:
  /// The first facet with different indices on its sides along the straight line to the light.
  std::optional<std::uint32_t> firstRefractingFacet(glm::dvec3 x, const LightEmitter& light,
                                                    double epsilon) const {
    glm::dvec3 dir = light.towards;
    double remaining = std::numeric_limits<double>::infinity();
    if (light.kind == LightEmitter::Kind::Point) {
      remaining = glm::length(light.position - x);
      dir = (light.position - x) / remaining;
    }
    for (int crossings = 0; crossings < 64; ++crossings) {
      const auto hit = mCaster.intersect(x, dir, 0, remaining);
      if (!hit) return std::nullopt;
      const std::uint32_t t = hit->triangle;
      if (mScene.media[mScene.inside[t]].eta != mScene.media[mScene.outside[t]].eta) return t;
      x += (hit->t + epsilon) * dir;
      remaining -= hit->t + epsilon;
    }
    return std::nullopt;
  }

  /// Steps from facet to facet towards the one holding its own solution; returns where it stopped.
  std::uint32_t walk(std::uint32_t t, const glm::dvec3& x, const LightEmitter& light) const {
    std::uint32_t previous = scene::FacetAdjacency::kNone;
    bool jumped = false;
    for (int step = 0; step < mMaxSteps; ++step) {
      const auto c = refractionPoint(mScene, t, mPlanes[t], x, light);
      if (!c || c->onFacet()) return t;
      if (!jumped) {  // once: land near the solution instead of stepping there edge by edge
        jumped = true;
        if (const auto landed = jumpTowards(*c, x); landed && *landed != t) {
          previous = scene::FacetAdjacency::kNone;
          t = *landed;
          continue;
        }
      }
      const glm::dvec3& b = c->barycentric;
      const int k = b.x <= b.y && b.x <= b.z ? 0 : (b.y <= b.z ? 1 : 2);
      const std::uint32_t next = mAdjacency.across(t, k);
      // Back where it came from: the solutions of two facets lie beyond each other's shared edge,
      // a gap between their beams (or a hole in the mesh).
      if (next == scene::FacetAdjacency::kNone || next == previous) return t;
      previous = t;
      t = next;
    }
    return t;
  }

  /// The facet the ray from x towards the plane's solution meets first, if it separates the same
  /// two media: on a curved surface its own solution lies a step or two away.
  std::optional<std::uint32_t> jumpTowards(const RefractedConnection& c,
                                           const glm::dvec3& x) const {
    const auto hit = mCaster.intersect(x, c.towardsPoint, 0, 2 * c.insideLength);
    if (!hit) return std::nullopt;
    const std::uint32_t h = hit->triangle;
    const bool sameMedia = (mScene.inside[h] == c.inner && mScene.outside[h] == c.outer) ||
                           (mScene.inside[h] == c.outer && mScene.outside[h] == c.inner);
    return sameMedia ? std::optional{h} : std::nullopt;
  }

  /// Floods out from `centre` over the facets within mGapSteps edge steps of the nearest facet
  /// with a solution (the walk's end counts as one), solving each: a band of facets that all bend
  /// light to x (a caustic of the curved shape, or its facets' overlapping beams) is found whole,
  /// and so is a second band a gap of up to mGapSteps facets away.
  void collectAround(std::uint32_t centre, const glm::dvec3& x, const LightEmitter& light,
                     std::vector<RefractedConnection>& out, ManifoldSearchStats& st) const {
    FloodScratch& f = floodScratch();
    f.begin(mScene.mesh.triangles.size());
    f.queue.assign(1, {centre, 0});
    f.visit(centre, 0);
    for (std::size_t head = 0; head < f.queue.size(); ++head) {
      const auto [t, gap] = f.queue[head];
      FloodScratch::Visit& v = f.visits[t];
      if (gap > v.gap) continue;  // reached again with a smaller gap since
      if (!v.done) {              // solve each facet once, even when reached again
        if (f.visited > mMaxFlood) {
          ++st.capped;
          break;
        }
        v.done = true;

        auto c = refractionPoint(mScene, t, mPlanes[t], x, light, true);
        if (c && c->onFacet() && setGeometryTerm(mScene, light, *c)) {
          v.solved = true;
          out.push_back(*c);
        }
      }
      const int nextGap = v.solved ? 1 : gap + 1;
      if (nextGap > mGapSteps) continue;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t n = mAdjacency.across(t, k);
        if (n != scene::FacetAdjacency::kNone && f.visit(n, nextGap))
          f.queue.push_back({n, nextGap});
      }
    }
  }

  /// A flood's per-facet marks, kept per thread and cleared in O(1) by an epoch stamp.
  struct FloodScratch {
    struct Visit {
      int gap = 0;  ///< the fewest edge steps from a facet with a solution
      bool solved = false, done = false;
    };
    std::vector<Visit> visits;
    std::vector<std::uint32_t> stamps;
    std::uint32_t epoch = 0;
    std::size_t visited = 0;
    std::vector<std::pair<std::uint32_t, int>> queue;

    void begin(std::size_t facets) {
      if (stamps.size() != facets || ++epoch == 0) {
        stamps.assign(facets, 0);
        visits.resize(facets);
        epoch = 1;
      }
      visited = 0;
    }
    /// Marks t reached with `gap`; true when that is new or fewer steps than before.
    bool visit(std::uint32_t t, int gap) {
      if (stamps[t] != epoch) {
        stamps[t] = epoch;
        visits[t] = Visit{gap};
        ++visited;
        return true;
      }
      if (visits[t].gap <= gap) return false;
      visits[t].gap = gap;
      return true;
    }
  };
  static FloodScratch& floodScratch() {
    thread_local FloodScratch scratch;
    return scratch;
  }

  const MediumScene& mScene;
  const scene::RayCaster& mCaster;
  scene::FacetAdjacency mAdjacency;
  std::vector<FacetPlane> mPlanes;
  int mGapSteps, mMaxSteps;
  std::size_t mMaxFlood;
};

}  // namespace lucent::reference
