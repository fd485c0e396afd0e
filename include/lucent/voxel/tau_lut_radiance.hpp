#pragma once
/// @file tau_lut_radiance.hpp
/// @brief The run time of Mochida et al. 2016 Sec. 2.2: the irradiance map and the
/// voxel-number map from each light's view, and B(x_out) = int_S E(x_in) Rd(x_in, x_out) dx_in
/// (Eq. 1) with Rd = e^{-tau} (Eq. 3) summed by a ring filter of taps around x_out's projection.
///
/// What the equations compute, stated (the paper leaves units open):
///  - Eq. 2, E(x_in) = Ft(eta, w_in) |N . w_in| I: the irradiance carried into the surface, W/mm^2
///    (scene::irradianceAt, with shadows); the map stores it per unit map area (E / |n . axis|).
///  - Eq. 3, Rd = e^{-tau}, is a transmittance: dimensionless, while Eq. 1 integrates it over an
///    area and needs 1/mm^2. We normalise it so that it integrates to one over a flat homogeneous
///    surface: Rd = (sigma_o^2 / 2 pi) e^{-tau}, sigma_o the extinction (per channel, at its
///    density) of the medium where the light leaves, since int_0^inf (sigma^2 / 2 pi)
///    e^{-sigma r} 2 pi r dr = 1. So B is W/mm^2; a flat homogeneous slab gives back all the light
///    (B = E); a slab of thickness d lit from behind gives B = E (1 + sigma d) e^{-sigma d}; no
///    medium (density 0) gives nothing. No albedo enters the model: absorption acts only through
///    tau. L = Ft(eta, w_out) B / pi (Eq. 1's prefactor) follows in the technique layer.
///  - tau (Eq. 4) uses the reduced extinction sigma_a + sigma_s' per medium (the path tracer's
///    sigma_t at g = 0), from the per-medium path lengths between the two points' surface voxels
///    (surface_paths.hpp), scaled from the voxel centres' distance to the points' own: the voxel
///    centres quantise distance by a voxel, which near x_out would make e^{-tau} exceed
///    e^{-sigma r} by up to e^{sigma h}. Two points in one voxel take that voxel's medium along
///    their chord.
///  - The integral: the 21-tap filter of translucent shadow maps as a ring filter
///    (ring_filter.hpp): a centre tap and rings of 5 taps placed by the importance of the
///    normalised kernel e^{-sigma r} 2 pi r of the object's densest medium, each tap weighted by
///    its stratum's mass over the kernel at its radius (the ratio estimator), so the homogeneous
///    flat case is exact and e^{-tau} replaces the kernel wherever the media make it differ.
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "../atlas/ring_filter.hpp"
#include "../atlas/translucent_shadow_map.hpp"
#include "../util/parallel.hpp"
#include "surface_paths.hpp"
#include "surface_voxel_lookup.hpp"

namespace lucent::voxel {

/// Taps on each ring of the filter (21 taps = the centre and 4 rings).
inline constexpr int kTapsPerRing = 5;

/// The ring filter of `taps` taps (1 + 5 L) for the kernel e^{-sigma r}, out to `domain` mm.
inline atlas::RingFilter tapFilter(const glm::dvec3& sigmaRef, int taps, double domain) {
  return atlas::makeRingFilter([&](double r) { return glm::exp(-sigmaRef * r); },
                               (taps - 1) / kTapsPerRing, kTapsPerRing, domain);
}

class TauLutRadiance {
 public:
  /// @param sigmaT per medium 1..M, mm^-1; @param sigmaFilter the extinction whose kernel places
  /// the taps (the object's densest).
  TauLutRadiance(std::vector<atlas::TranslucentShadowMap> maps, const SurfacePaths& paths,
                 const SurfaceVoxelLookup& lookup, std::vector<glm::dvec3> sigmaT,
                 const glm::dvec3& sigmaFilter, int taps, double domain,
                 const util::ParallelFor& parallelFor = util::serialFor)
      : mMaps(std::move(maps)),
        mPaths(paths),
        mLookup(lookup),
        mSigmaT(std::move(sigmaT)),
        mFilter(tapFilter(sigmaFilter, taps, domain)) {
    if (mSigmaT.size() != std::size_t(mPaths.media()))
      throw std::invalid_argument("the scene has " + std::to_string(mSigmaT.size()) +
                                  " media, the optical-thickness table " +
                                  std::to_string(mPaths.media()) + ": prepare again");
    for (const auto& map : mMaps) {
      std::vector<std::int32_t> numbers(map.texelCount(), -1);
      parallelFor(numbers.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
          if (map.covered(i)) numbers[i] = mLookup.numberOf(map.position(i));
      });
      mNumberMaps.push_back(std::move(numbers));
    }
  }

  /// Whether each point turns the tap pattern by its own angle (a hash of its position).
  void setRotatedPattern(bool rotated) { mRotated = rotated; }

  /// B(x_out), W/mm^2 (Eq. 1 without its Ft / pi).
  glm::dvec3 radiosity(const glm::dvec3& xo) const {
    const std::int32_t out = mLookup.numberOf(xo);
    glm::dvec3 b(0);
    if (out < 0) return b;
    for (std::size_t l = 0; l < mMaps.size(); ++l) {
      const auto& map = mMaps[l];
      const auto& numbers = mNumberMaps[l];
      const double turn = mRotated ? turnOf(xo, map.texelSize()) : 0.0;
      map.forEachTap(
          xo, mFilter,
          [&](std::size_t texel, std::size_t k, double share) {
            const std::int32_t in = numbers[texel];
            if (in < 0) return;
            const glm::dvec3 tau = opticalThickness(in, map.position(texel), out, xo);
            b += mFilter.tapEstimate(k, share, map.density(texel) * glm::exp(-tau));
          },
          turn);
    }
    const glm::dvec3 sigmaOut = mediumAt(out);
    return b * (sigmaOut * sigmaOut / (2 * optics::kPi));
  }

  const atlas::RingFilter& filter() const { return mFilter; }
  /// The voxel-number map of light l (texel -> surface voxel number, -1 where uncovered).
  const std::vector<std::int32_t>& numberMap(std::size_t l) const { return mNumberMaps[l]; }

 private:
  /// An angle in [0, 2 pi / 5) from x_o's position quantised to a quarter texel: deterministic, and
  /// uncorrelated between neighbouring pixels.
  static double turnOf(const glm::dvec3& xo, double texel) {
    const glm::ivec3 q(glm::floor(xo / (0.25 * texel)));
    std::uint32_t h = std::uint32_t(q.x) * optics::kTurnHashX ^
                      std::uint32_t(q.y) * optics::kTurnHashY ^
                      std::uint32_t(q.z) * optics::kTurnHashZ;
    h ^= h >> 16, h *= optics::kTurnHashMix, h ^= h >> 16;
    return 2 * optics::kPi / kTapsPerRing * double(h) / 4294967296.0;
  }

  /// tau per channel from surface voxel a (point xa) to b (point xb).
  glm::dvec3 opticalThickness(std::int32_t a, const glm::dvec3& xa, std::int32_t b,
                              const glm::dvec3& xb) const {
    const double chord = glm::length(xb - xa);
    if (a == b) return mediumAt(a) * chord;
    float length[256];
    mPaths.lengths(a, b, length);
    const double scale = chord / glm::length(mPaths.centre(b) - mPaths.centre(a));
    glm::dvec3 tau(0);
    for (std::size_t m = 0; m < mSigmaT.size(); ++m)
      tau += mSigmaT[m] * (double(length[m]) * scale);
    return tau;
  }

  /// sigma_t of surface voxel a's medium at its density.
  glm::dvec3 mediumAt(std::int32_t a) const {
    const MediaGrid& grid = mPaths.grid();
    const std::size_t i = grid.index(grid.voxelOf(mPaths.centre(a)));
    const std::uint8_t m = grid.medium[i];
    return m == kNoMedium ? glm::dvec3(0) : mSigmaT[m - 1u] * grid.densityAt(i);
  }

  std::vector<atlas::TranslucentShadowMap> mMaps;
  const SurfacePaths& mPaths;
  const SurfaceVoxelLookup& mLookup;
  std::vector<glm::dvec3> mSigmaT;
  atlas::RingFilter mFilter;
  bool mRotated = true;
  std::vector<std::vector<std::int32_t>> mNumberMaps;
};

}  // namespace lucent::voxel
