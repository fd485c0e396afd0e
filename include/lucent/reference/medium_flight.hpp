#pragma once
/// @file medium_flight.hpp
/// @brief One flight of a path inside a medium, up to its next collision or the surface ahead:
/// shared by the volumetric path tracer and the random walk. In two halves, so the path tracer can
/// join light subpaths along the segment before the flight's weight is applied.
#include <limits>
#include <optional>

#include <glm/vec3.hpp>

#include "../scene/ray_caster.hpp"
#include "../scene/surface_clearance_grid.hpp"
#include "path_tracer_settings.hpp"
#include "volume_sampling.hpp"

namespace lucent::reference {

struct MediumFlight {
  std::optional<scene::RayHit> hit;  ///< the surface ahead (unset for a flight that surely ends)
  double t = 0;                      ///< the collision distance, once drawn
  bool drawnFirst = false;           ///< a homogeneous distance drawn before any ray cast
  bool clear = false;                ///< that distance ends short of every surface: no ray cast

  /// Starts the flight from `pos` along `dir` in medium `m`. In a homogeneous medium (unless
  /// `mustCast`: the caller needs the whole segment) the distance is drawn first, and one that ends
  /// short of every surface (the clearance grid's bound) needs no ray cast. False when no surface
  /// lies ahead: the path leaked out of a mesh that is not closed (counted).
  bool begin(const Medium& m, const scene::RayCaster& caster,
             const scene::SurfaceClearanceGrid& clearance, const glm::dvec3& pos,
             const glm::dvec3& dir, int hero, util::Rng& rng, double rayEpsilon, bool mustCast,
             PathTracerStats& st) {
    drawnFirst = m.homogeneous() && !mustCast;
    t = drawnFirst ? drawHomogeneousFlight(m, hero, rng) : 0;
    clear = drawnFirst && t < clearance.lowerBound(pos) - 4 * rayEpsilon;
    if (clear) {
      ++st.clearFlights;
      return true;
    }
    hit = caster.intersect(pos, dir, 0, std::numeric_limits<double>::infinity());
    if (!hit) ++st.leakedPaths;
    return hit.has_value();
  }

  /// Ends it: true for a collision at distance t (the weight takes its factors), false when it
  /// reaches the surface `hit`.
  bool collides(const Medium& m, const glm::dvec3& pos, const glm::dvec3& dir, int hero,
                util::Rng& rng, HeroChannelWeight& w, MediumSamplingStats& stats) {
    if (drawnFirst)
      return finishHomogeneousFlight(m, t, clear ? std::numeric_limits<double>::infinity() : hit->t,
                                     w);
    return sampleFlight(m, pos, dir, hit->t, hero, rng, w, t, stats);
  }
};

}  // namespace lucent::reference
