#pragma once
/// @file pencil_beam_mc.hpp
/// @brief Monte Carlo truth for the dipole's own setting: a normally incident pencil beam on a
/// semi-infinite homogeneous medium (MCML's experiment, Wang et al. 1995). Photons enter at the
/// origin (the specular part is not counted, as in the dipole's Rd), take exponential free flights,
/// are weighted by the albedo at each collision (implicit absorption, Russian roulette below a
/// weight threshold), scatter by Henyey-Greenstein, and at the surface are reflected back with the
/// exact Fresnel probability or escape; escapes are tallied in rings. Output: Rd(r) in mm^-2 with
/// standard errors, and the total.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "../optics/fresnel.hpp"
#include "../optics/phase_hg.hpp"
#include "../util/basis.hpp"
#include "../util/parallel.hpp"
#include "../util/rng.hpp"
#include "volume_sampling.hpp"

namespace lucent::reference {

struct PencilBeamSettings {
  double sigmaA = 0.01;  ///< mm^-1
  double sigmaS = 1.0;   ///< mm^-1 (not reduced)
  double g = 0.0;        ///< HG mean cosine
  double eta = 1.3;      ///< relative index of the medium; 1 = index-matched boundary
  std::uint64_t photons = 1000000;
  double rMax = 10.0;  ///< mm; escapes beyond it count in the total only
  int rings = 100;
  std::uint64_t seed = 1;
  /// Photons still inside after this many collisions are dropped (and counted): only albedo-1 media
  /// need it.
  std::uint64_t maxCollisions = 1000000;
  /// Only escapes after this many scattering events or more are tallied: 2 gives the multiple
  /// scattering alone (what diffusion models), 1 everything (the beam cannot leave unscattered).
  std::uint64_t minOrder = 1;
  /// And at most this many: 1 gives the single scattering alone.
  std::uint64_t maxOrder = std::numeric_limits<std::uint64_t>::max();
};

struct RadialProfile {
  std::vector<double> rInner, rOuter;  ///< ring bounds, mm
  std::vector<double> rd, rdStdError;  ///< mm^-2
  double total = 0,
         totalStdError = 0;  ///< fraction of the entering light that leaves through the surface
  std::uint64_t droppedPhotons =
      0;  ///< hit maxCollisions (bias bound: at most this fraction of weight)
};

namespace detail {
/// Tallies of a fixed block of photons: sums of weights and squared weights per photon.
struct BeamTally {
  std::vector<double> sum, sumSq;
  double total = 0, totalSq = 0;
  std::uint64_t dropped = 0;
};

inline void tracePhoton(const PencilBeamSettings& s, util::Rng& rng, BeamTally& tally,
                        double ringWidth) {
  const double sigmaT = s.sigmaA + s.sigmaS, albedo = s.sigmaS / sigmaT;
  glm::dvec3 p(0), d(0, 0, 1);  // z > 0 is inside
  double w = 1;
  for (std::uint64_t collisions = 0;; ++collisions) {
    if (collisions >= s.maxCollisions) {
      ++tally.dropped;
      return;
    }
    const double step = -std::log(1.0 - rng.uniform()) / sigmaT;
    if (p.z + step * d.z <= 0) {  // reaches the surface first
      const double t = -p.z / d.z;
      const glm::dvec3 exit = p + t * d;
      const double cosInside = -d.z;
      // Leaving the medium: from index eta into 1, relative index 1/eta (TIR beyond the critical
      // angle).
      if (rng.uniform() < optics::fresnelReflectance(cosInside, 1.0 / s.eta)) {
        p = exit;
        p.z = 0;
        d.z = -d.z;  // specular reflection back inside; continue the remaining flight
        const double remaining = step - t;
        p += remaining * d;
        if (p.z <= 0) p.z = 1e-12;
      } else {
        if (collisions < s.minOrder || collisions > s.maxOrder)
          return;  // the order is not asked for
        const double r = std::hypot(exit.x, exit.y);
        const std::size_t ring = std::size_t(r / ringWidth);
        if (ring < tally.sum.size()) {
          tally.sum[ring] += w;
          tally.sumSq[ring] += w * w;
        }
        tally.total += w;
        tally.totalSq += w * w;
        return;
      }
    } else {
      p += step * d;
    }
    w *= albedo;
    if (collisions + 1 > s.maxOrder) return;  // scattered more often than the tally takes
    if (w < 1e-4) {  // Russian roulette: unbiased termination of low-weight photons
      if (rng.uniform() >= 0.1) return;
      w *= 10;
    }
    d = reference::scatterHG(d, s.g, rng);
  }
}
}  // namespace detail

/// Deterministic for a fixed seed: photons are split into fixed blocks, each with its own
/// generator, and the blocks are summed in order whatever the thread count.
inline RadialProfile simulatePencilBeam(const PencilBeamSettings& s,
                                        const util::ParallelFor& parallelFor = util::serialFor,
                                        const util::Progress& progress = {}) {
  const int rings = std::max(1, s.rings);
  const double ringWidth = s.rMax / rings;
  constexpr std::size_t kBlocks = 256;
  std::vector<detail::BeamTally> tallies(kBlocks);
  std::vector<char> done(kBlocks, 0);
  parallelFor(kBlocks, [&](std::size_t begin, std::size_t end) {
    for (std::size_t b = begin; b < end; ++b) {
      detail::BeamTally& t = tallies[b];
      t.sum.assign(std::size_t(rings), 0.0);
      t.sumSq.assign(std::size_t(rings), 0.0);
      util::Rng rng(s.seed * 1000003ULL + b);
      const std::uint64_t count = s.photons / kBlocks + (b < s.photons % kBlocks ? 1 : 0);
      for (std::uint64_t i = 0; i < count; ++i) detail::tracePhoton(s, rng, t, ringWidth);
      if (progress)
        progress(double(b + 1) / double(kBlocks));  // coarse: blocks finish out of order
    }
  });
  RadialProfile out;
  std::vector<double> sum(std::size_t(rings), 0.0), sumSq(std::size_t(rings), 0.0);
  double total = 0, totalSq = 0;
  for (const auto& t : tallies) {
    for (int i = 0; i < rings; ++i)
      sum[std::size_t(i)] += t.sum[std::size_t(i)],
          sumSq[std::size_t(i)] += t.sumSq[std::size_t(i)];
    total += t.total, totalSq += t.totalSq;
    out.droppedPhotons += t.dropped;
  }
  const double n = double(std::max<std::uint64_t>(1, s.photons));
  // Each photon contributes once at most: the standard error of a mean of n independent
  // contributions.
  auto stdError = [n](double sw, double sw2) {
    return std::sqrt(std::max(0.0, sw2 / n - (sw / n) * (sw / n)) / n);
  };
  for (int i = 0; i < rings; ++i) {
    const double r0 = i * ringWidth, r1 = (i + 1) * ringWidth,
                 area = optics::kPi * (r1 * r1 - r0 * r0);
    out.rInner.push_back(r0);
    out.rOuter.push_back(r1);
    out.rd.push_back(sum[std::size_t(i)] / n / area);
    out.rdStdError.push_back(stdError(sum[std::size_t(i)], sumSq[std::size_t(i)]) / area);
  }
  out.total = total / n;
  out.totalStdError = stdError(total, totalSq);
  return out;
}

}  // namespace lucent::reference
