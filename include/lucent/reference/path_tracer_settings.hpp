#pragma once
/// @file path_tracer_settings.hpp
/// @brief The knobs of the volumetric path tracer and the counts it reports.
#include <cstdint>

#include "volume_sampling.hpp"

namespace lucent::reference {

/// Which paths count, by their number of volume scattering events.
enum class ScatteringOrders { All, Single, Multiple };

/// How environment light reaches the medium: paths that escape look it up (default: every order),
/// or it is sampled like a delta light and joined to camera vertices (the estimator delta lights
/// must use behind a refracting boundary; offered for environments so the two can be checked
/// against each other).
enum class EnvironmentStrategy { Escape, Connect };

/// How point and directional lights reach a medium behind a refracting boundary: manifold
/// next-event estimation from every scattering vertex through one refraction (light subpaths only
/// for light that reflected on its way in), or light subpaths joined to camera segments for all of
/// it (the older estimator: no single scattering, heavy-tailed; kept to check the two against each
/// other).
enum class DeltaLightStrategy { Manifold, Joins };

/// How a path picks the channel it draws its distances with (hero_channel_weight.hpp): uniformly,
/// or in proportion to the object medium's total diffuse reflectance per channel (the share of
/// the image each channel is expected to hold), mixed with a fifth of uniform so none is starved.
enum class HeroChoice { Reflectance, Uniform };

struct PathTracerSettings {
  int samplesPerPixel = 16;
  std::uint64_t seed = 1;
  /// Surface and scattering events per subpath before it is dropped (counted; only albedo-1 media
  /// of many mean free paths reach it).
  std::uint64_t maxEvents = 200000;
  bool subsurfaceOnly =
      false;  ///< the camera's first surface transmits (weight Ft), never reflects
  ScatteringOrders orders = ScatteringOrders::All;
  EnvironmentStrategy environment = EnvironmentStrategy::Escape;
  /// Escaping paths count only if two successive scattering events see each other along a straight
  /// segment: exactly the paths a delta light can reach through a refracting boundary (for checks).
  bool connectableOnly = false;
  DeltaLightStrategy deltaLights = DeltaLightStrategy::Manifold;
  HeroChoice heroChoice = HeroChoice::Reflectance;
  /// Edge steps without a refraction point the manifold search floods across from the facets with
  /// one: a curved surface focuses light through bands of facets (manifold_next_event.hpp).
  int manifoldGap = 2;
  int lightSubpaths =
      1;  ///< light subpaths per light and camera sample (delta lights, Fresnel boundary)
  int maxLightVertices = 16;  ///< targets kept per light subpath
  double guideRadius =
      0;  ///< mm: scale of the light-entry sampling around the camera's entry point; 0 = auto
  double rayEpsilon = 1e-6;  ///< mm: offset of new rays off a surface
};

/// What the manifold next-event searches found (manifold_next_event.hpp).
struct ManifoldSearchStats {
  std::uint64_t searches = 0, solutions = 0;
  std::uint64_t noSolution = 0;  ///< searches that found no refraction point (shadow, or a miss)
  std::uint64_t multiple = 0;    ///< searches with two or more solutions (overlapping beams)
  std::uint64_t capped = 0;      ///< floods that reached their facet cap: more may lie beyond

  void add(const ManifoldSearchStats& o) {
    searches += o.searches, solutions += o.solutions, noSolution += o.noSolution;
    multiple += o.multiple, capped += o.capped;
  }
};

struct PathTracerStats {
  std::uint64_t cameraSamples = 0, scatterEvents = 0;
  std::uint64_t lightSubpaths = 0, lightVertices = 0, connections = 0;
  std::uint64_t truncatedPaths = 0;  ///< reached maxEvents (their remaining weight is lost)
  std::uint64_t leakedPaths =
      0;  ///< found no surface from inside a medium (an open or broken mesh)
  std::uint64_t mediumMismatches =
      0;  ///< a surface's declared media disagree with the path's (nesting errors)
  std::uint64_t nonFiniteSamples = 0;      ///< dropped NaN/inf estimates (must stay 0)
  std::uint64_t rouletteTerminations = 0;  ///< camera paths ended by Russian roulette
  std::uint64_t clearFlights = 0;  ///< camera flights that surely ended short of every surface
  MediumSamplingStats medium;
  ManifoldSearchStats manifold;

  void add(const PathTracerStats& o) {
    cameraSamples += o.cameraSamples, scatterEvents += o.scatterEvents;
    lightSubpaths += o.lightSubpaths, lightVertices += o.lightVertices,
        connections += o.connections;
    truncatedPaths += o.truncatedPaths, leakedPaths += o.leakedPaths,
        mediumMismatches += o.mediumMismatches;
    nonFiniteSamples += o.nonFiniteSamples,
        medium.majorantViolations += o.medium.majorantViolations;
    rouletteTerminations += o.rouletteTerminations, clearFlights += o.clearFlights;
    manifold.add(o.manifold);
  }
};

inline bool orderCounts(ScatteringOrders orders, int scatteringEvents) {
  switch (orders) {
    case ScatteringOrders::Single:
      return scatteringEvents == 1;
    case ScatteringOrders::Multiple:
      return scatteringEvents >= 2;
    default:
      return true;
  }
}

}  // namespace lucent::reference
