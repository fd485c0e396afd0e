#pragma once
/// @file tsis_evaluator.hpp
/// @brief Eq. 11 of Chang et al. 2008:
///   L(x_o, w_o) = Ft(eta, w_o) / pi * sum_i w_i f(|x_i - x_o|),   w_i = E'(x_i) / (p(x_i) N)  (Eq.
///   10)
/// with f = Rd (TSIS) or Rd Wg (the hybrid's global term), looked up in a 1-D table (Sec. 3) or,
/// for f = Rd, evaluated exactly by the truth's kernel. Ft comes from a 1-D table too. Per pixel
/// (every shaded point sums all samples) or per vertex (sum at the mesh's vertices, then
/// interpolate B across each triangle; cheaper when triangles are larger than pixels).
#include <atomic>
#include <memory>
#include <vector>

#include "../optics/fresnel_table.hpp"
#include "../reference/dipole_truth.hpp"
#include "../reference/radial_table_sum.hpp"
#include "../reference/vertex_radiosity.hpp"
#include "importance_samples.hpp"

namespace lucent::atlas {

class TsisEvaluator {
 public:
  /// Exact Rd (the float kernel of the truth). @pre profile.isPolePair()
  TsisEvaluator(ImportanceSamples samples, const optics::Profile<float>& profile)
      : mSamples(std::move(samples)),
        mKernel(reference::RdKernelConstants::from(profile)),
        mFt(profile.eta) {}
  /// A tabulated radial profile (Rd or a weighted Rd); @param eta for Ft.
  TsisEvaluator(ImportanceSamples samples, const optics::RadialTable<float>& profile, float eta)
      : mSamples(std::move(samples)),
        mTable(std::make_shared<reference::PlanarRadialTable>(profile)),
        mFt(eta) {}

  /// B(x_o) (Eq. 10).
  glm::dvec3 radiosity(const glm::dvec3& xo) const {
    const reference::RdKernelSamples s{
        mSamples.x.data(),    mSamples.y.data(),    mSamples.z.data(), mSamples.w[0].data(),
        mSamples.w[1].data(), mSamples.w[2].data(), mSamples.size()};
    double out[3];
    if (mTable)
      reference::radialTableSum(s, *mTable, float(xo.x), float(xo.y), float(xo.z), out);
    else
      reference::rdSumFloat(s, mKernel, float(xo.x), float(xo.y), float(xo.z), out);
    return {out[0], out[1], out[2]};
  }

  /// Eq. 11.
  glm::dvec3 radiance(const glm::dvec3& xo, double cosOut) const {
    return radiosity(xo) * (double(mFt(float(cosOut))) / optics::kPi);
  }
  double fresnelOverPi(double cosOut) const { return double(mFt(float(cosOut))) / optics::kPi; }

  const ImportanceSamples& samples() const { return mSamples; }

 private:
  ImportanceSamples mSamples;
  reference::RdKernelConstants mKernel{};
  std::shared_ptr<const reference::PlanarRadialTable> mTable;
  optics::FtTable<float> mFt;
};

/// Any radiosity evaluator B(x_o) summed at the mesh's vertices and interpolated across triangles.
/// @tparam Radiosity has radiosity(dvec3) and fresnelOverPi(cos).
template <class Radiosity>
class PerVertexShading {
 public:
  PerVertexShading(const Radiosity& eval, const scene::TriangleMesh& mesh,
                   const util::ParallelFor& parallelFor = util::serialFor,
                   const util::Progress& progress = {})
      : mEval(eval), mMesh(mesh), mB(mesh.positions.size()) {
    std::atomic<std::size_t> done{0};
    parallelFor(mB.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
        mB[i] = eval.radiosity(glm::dvec3(mesh.positions[i]));
      if (progress) progress(double(done += end - begin) / double(mB.size()));
    });
  }

  glm::dvec3 radiance(const reference::ShadingPoint& hit) const {
    return reference::interpolateAtHit(mMesh, mB, hit) * mEval.fresnelOverPi(hit.cosOut);
  }
  const std::vector<glm::dvec3>& vertexRadiosity() const { return mB; }

 private:
  const Radiosity& mEval;
  const scene::TriangleMesh& mMesh;
  std::vector<glm::dvec3> mB;
};

}  // namespace lucent::atlas
