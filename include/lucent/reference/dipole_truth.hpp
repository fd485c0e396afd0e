#pragma once
/// @file dipole_truth.hpp
/// @brief The brute-force dipole truth: irradiance at dense surface samples and the exact Rd sum
/// for every shaded point, L(xo, wo) = (1/pi) Ft(eta, wo) B(xo), B(xo) = sum_i E_i A_i Rd(|x_i -
/// xo|) (Chang et al. 2008 Eq. 2-3). The model truth every dipole technique is
/// measured against.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "../image/image.hpp"
#include "../optics/dipole_lut.hpp"
#include "../optics/profile.hpp"
#include "../scene/camera.hpp"
#include "../scene/irradiance.hpp"
#include "../util/parallel.hpp"
#include "near_field.hpp"
#include "radial_table_sum.hpp"
#include "rd_sum_kernel.hpp"
#include "surface_samples.hpp"

namespace lucent::reference {

/// Sample spacing for a converged truth: a fraction of the smallest mean free path (where Rd varies
/// fastest), never coarser than diag/minSamplesPerDiagonal (the geometry and the lighting must be
/// resolved too), and coarsened if needed to respect a sample budget.
struct SpacingChoice {
  double spacing = 0;
  double meanFreePath = 0;
  bool budgetLimited = false;  ///< true: the budget forced a spacing coarser than asked for
  std::size_t count = 0;       ///< samples at that spacing (above the budget when triangles are)
};

inline SpacingChoice chooseSpacing(const scene::TriangleMesh& mesh, double minMeanFreePath,
                                   double fractionOfMeanFreePath = 0.5,
                                   std::size_t maxSamples = 2000000,
                                   double minSamplesPerDiagonal = 64) {
  SpacingChoice c;
  c.meanFreePath = minMeanFreePath;
  const double diag = mesh.bounds().diagonal();
  c.spacing = std::min(fractionOfMeanFreePath * minMeanFreePath, diag / minSamplesPerDiagonal);
  // Below 1e-9 of the diagonal every count saturates; the floor also keeps the coarsening below
  // moving (1.25 times a subnormal spacing rounds back to itself).
  c.spacing = std::max(c.spacing, 1e-9 * diag);
  // Each triangle gets at least one sample, so coarsening stops once every triangle has one (the
  // spacing then exceeds the longest edge): a budget below the triangle count cannot be met by
  // spacing alone.
  std::size_t count = countSurfaceSamples(mesh, c.spacing);
  while (count > maxSamples && count > mesh.triangles.size()) {
    c.spacing *= 1.25;
    c.budgetLimited = true;
    count = countSurfaceSamples(mesh, c.spacing);
  }
  c.count = count;
  return c;
}

/// @tparam T the scalar Rd is evaluated in; sums are always accumulated in double.
template <class T>
class DipoleTruth {
 public:
  struct Stats {
    std::size_t samples = 0;     ///< surface samples
    std::size_t litSamples = 0;  ///< samples with non-zero irradiance (only these enter the sum)
    double spacing = 0;          ///< mm
    glm::dvec3 transmittedPower{0};  ///< sum E_i A_i: the power entering the surface
  };

  DipoleTruth(const SurfaceSamples& samples, const optics::Profile<T>& profile,
              const std::vector<scene::Light>& lights, const scene::RayCaster& caster,
              const scene::IrradianceSettings& irr,
              const util::ParallelFor& parallelFor = util::serialFor,
              const util::Progress& progress = {})
      : mProfile(profile) {
    mStats.samples = samples.size();
    mStats.spacing = samples.spacing;
    std::vector<glm::dvec3> weighted(samples.size());
    std::atomic<std::size_t> done{0};
    parallelFor(samples.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
        weighted[i] = scene::irradianceAt(samples.position[i], samples.normal[i],
                                          samples.faceNormal[i], lights, caster, irr, i) *
                      samples.area[i];
      if (progress) progress(double(done += end - begin) / double(samples.size()));
    });
    mNear = NearField(samples.position, weighted, samples.area, samples.spacing);
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const glm::dvec3& w = weighted[i];
      if (!(w.x > 0 || w.y > 0 || w.z > 0)) continue;
      mStats.transmittedPower += w;
      mArea.push_back(samples.area[i]);
      mX.push_back(T(samples.position[i].x));
      mY.push_back(T(samples.position[i].y));
      mZ.push_back(T(samples.position[i].z));
      for (int c = 0; c < 3; ++c) mW[c].push_back(T(w[c]));
    }
    mStats.litSamples = mX.size();
    if (mProfile.isPolePair())
      mKernel = RdKernelConstants::from(mProfile);
    else if (!samples.position.empty())
      mTable = profileTable(samples);
  }

  /// B(xo) = sum_i E_i A_i Rd(|x_i - xo|) (Eq. 3), mm^-2 times the irradiance unit, with the
  /// samples within nearField().radius() of xo integrated as a disc (near_field.hpp).
  glm::dvec3 radiosity(const glm::dvec3& xo) const {
    return pointSum(xo) + mNear.correction(xo, mProfile);
  }

  /// The plain point sum of Eq. 3 (what a spacing far below the mean free path converges with).
  glm::dvec3 pointSum(const glm::dvec3& xo) const {
    if constexpr (std::is_same_v<T, float>)
      return radiosityFloatKernel(xo);  // vectorised, same sum
    // The dipoles' channels directly: the profile's per-call dispatch costs 3x here.
    if (mProfile.isPolePair()) return scalarSum(xo, mPoles.channel);
    return scalarSum(xo, mProfile.channel);
  }

  /// L(xo, wo) = (1/pi) Ft(eta, wo) B(xo) (Eq. 2); cosOut = n.wo at xo.
  glm::dvec3 radiance(const glm::dvec3& xo, double cosOut) const {
    const double ft = optics::fresnelTransmittance(cosOut, double(mProfile.eta));
    return radiosity(xo) * (ft * double(mProfile.exitScale) / optics::kPi);
  }

  const Stats& stats() const { return mStats; }
  const NearField& nearField() const { return mNear; }
  const optics::Profile<T>& profile() const { return mProfile; }
  /// Nodes of the radial table the float sum looks up (0: the closed-form kernel).
  std::size_t tableNodes() const { return mTable ? mTable->size() : 0; }

  /// The lit samples, structure-of-arrays: positions, E_i A_i per channel, and areas A_i.
  std::size_t litCount() const { return mX.size(); }
  glm::dvec3 litPosition(std::size_t i) const {
    return {double(mX[i]), double(mY[i]), double(mZ[i])};
  }
  glm::dvec3 litPower(std::size_t i) const {
    return {double(mW[0][i]), double(mW[1][i]), double(mW[2][i])};
  }
  double litArea(std::size_t i) const { return mArea[i]; }

 private:
  glm::dvec3 radiosityFloatKernel(const glm::dvec3& xo) const {
    const RdKernelSamples samples{mX.data(),    mY.data(),    mZ.data(), mW[0].data(),
                                  mW[1].data(), mW[2].data(), mX.size()};
    double out[3];
    if (mTable)
      radialTableSum(samples, *mTable, float(xo.x), float(xo.y), float(xo.z), out);
    else
      rdSumFloat(samples, mKernel, float(xo.x), float(xo.y), float(xo.z), out);
    return {out[0], out[1], out[2]};
  }

  template <class Channel>
  glm::dvec3 scalarSum(const glm::dvec3& xo, const Channel (&channel)[3]) const {
    const T ox = T(xo.x), oy = T(xo.y), oz = T(xo.z);
    double sum[3] = {0, 0, 0};
    const std::size_t n = mX.size();
    for (std::size_t i = 0; i < n; ++i) {
      const T dx = mX[i] - ox, dy = mY[i] - oy, dz = mZ[i] - oz;
      const T r = std::sqrt(dx * dx + dy * dy + dz * dz);
      for (int c = 0; c < 3; ++c) sum[c] += double(mW[c][i] * channel[c].rd(r));
    }
    return {sum[0], sum[1], sum[2]};
  }

  /// The profile as a radial table to the largest distance between two samples (the bounding box's
  /// diagonal), with RadialTable's stated bound.
  std::shared_ptr<const PlanarRadialTable> profileTable(const SurfaceSamples& samples) const {
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (const auto& p : samples.position) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const float rMax = float(std::max(glm::length(hi - lo), 1e-9) * 1.001);
    const auto table = optics::radialTable(mProfile, rMax);
    return std::make_shared<PlanarRadialTable>(table);
  }

  optics::Profile<T> mProfile;
  optics::Dipole<T> mPoles = mProfile.poles();  ///< the same, when it is a dipole
  RdKernelConstants mKernel{};
  std::shared_ptr<const PlanarRadialTable> mTable;
  std::vector<T> mX, mY, mZ, mW[3];
  std::vector<double> mArea;
  NearField mNear;
  Stats mStats;
};

/// A point seen by the camera: where, and how it is seen.
struct ShadingPoint {
  glm::dvec3 position;
  double cosOut = 0;  ///< n . (direction to the eye), clamped to [0, 1]
  std::uint32_t triangle = 0;
  double u = 0,
         v = 0;  ///< barycentrics of the triangle's vertices 1 and 2 (for per-vertex shading)
};

/// Whether an evaluator shades from the whole ShadingPoint (e.g. per-vertex interpolation) rather
/// than from (position, cosOut).
template <class E, class = void>
struct ShadesPoints : std::false_type {};
template <class E>
struct ShadesPoints<E, std::void_t<decltype(std::declval<const E&>().radiance(
                           std::declval<const ShadingPoint&>()))>> : std::true_type {};

/// The first surface hit through each pixel centre, or nothing (background).
inline std::vector<std::optional<ShadingPoint>> primaryHits(
    const scene::PinholeCamera& camera, const scene::TriangleMesh& mesh,
    const std::vector<glm::vec3>& vertexNormals, const scene::RayCaster& caster,
    const util::ParallelFor& parallelFor) {
  std::vector<std::optional<ShadingPoint>> hits(std::size_t(camera.width) * camera.height);
  parallelFor(hits.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const scene::Ray ray = camera.primaryRay(double(i % camera.width), double(i / camera.width));
      const auto hit =
          caster.intersect(ray.origin, ray.direction, 0, std::numeric_limits<double>::infinity());
      if (!hit) continue;
      const glm::dvec3 n = scene::shadingNormal(mesh, vertexNormals, hit->triangle,
                                                glm::dvec3(1 - hit->u - hit->v, hit->u, hit->v));
      const double cosOut = std::clamp(-glm::dot(n, ray.direction), 0.0, 1.0);
      hits[i] =
          ShadingPoint{ray.origin + hit->t * ray.direction, cosOut, hit->triangle, hit->u, hit->v};
    }
  });
  return hits;
}

/// Renders any evaluator with radiance(xo, cosOut) (the truth, or an approximation of its sum):
/// radiance in RGB, coverage in A.
template <class Evaluator>
image::Image renderTruth(const Evaluator& truth, const scene::PinholeCamera& camera,
                         const std::vector<std::optional<ShadingPoint>>& hits,
                         const util::ParallelFor& parallelFor,
                         const util::Progress& progress = {}) {
  image::Image img(camera.width, camera.height);
  std::atomic<std::size_t> done{0};
  const std::size_t rows = std::size_t(camera.height);
  parallelFor(rows, [&](std::size_t begin, std::size_t end) {
    for (std::size_t y = begin; y < end; ++y) {
      for (int x = 0; x < camera.width; ++x) {
        const auto& hit = hits[y * camera.width + x];
        if (!hit) continue;
        glm::dvec3 l;
        if constexpr (ShadesPoints<Evaluator>::value)
          l = truth.radiance(*hit);
        else
          l = truth.radiance(hit->position, hit->cosOut);
        img.at(x, int(y)) = glm::vec4(glm::vec3(l), 1.0f);
      }
      if (progress) progress(double(++done) / double(rows));
    }
  });
  return img;
}

}  // namespace lucent::reference
