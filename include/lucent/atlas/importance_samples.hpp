#pragma once
/// @file importance_samples.hpp
/// @brief Stage 2 of Chang et al. 2008 (Sec. 3): N incident points drawn over the atlas
/// with p = E'/E'avg (Eq. 9), by the mipmap ICDF (Fig. 2b) or the row-major ICDF (Fig. 2a), from
/// independent or stratified 2-D points. Each sample carries its Eq. 10 weight per channel,
///   w_c = E'_c(texel) / (p(texel) N),
/// so B_c(x_o) ~= sum_i w_c,i Rd_c(|x_i - x_o|). With white light w_c = E'avg_c / N, exactly Eq.
/// 10; with coloured light p follows R+G+B and the weights keep every channel unbiased.
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "../util/rng.hpp"
#include "irradiance_atlas.hpp"
#include "mip_icdf.hpp"

namespace lucent::atlas {

enum class TexelSampler { Mipmap, RowMajor };
enum class SamplePattern { Independent, Stratified };

struct SamplingOptions {
  int samples = 1600;
  TexelSampler sampler = TexelSampler::Mipmap;
  SamplePattern pattern = SamplePattern::Stratified;
  bool jitterInTexel =
      true;  ///< place the sample where in the texel the 2-D point fell (else its centre)
  std::uint64_t seed = 1;
};

/// Structure-of-arrays, float: the layout the summation kernels and a GPU texture use.
struct ImportanceSamples {
  std::vector<float> x, y, z, w[3];
  std::size_t size() const { return x.size(); }
};

/// The i-th of n stratified points: Hammersley (i + 1/2)/n against the base-2 radical inverse,
/// shifted on the torus by a random offset (Cranley-Patterson), so every n, not only squares, is
/// stratified.
inline void stratifiedPoint(std::uint32_t i, std::uint32_t n, double shift1, double shift2,
                            double& u1, double& u2) {
  std::uint32_t bits = i;
  bits = (bits << 16) | (bits >> 16);
  bits = ((bits & 0x55555555u) << 1) | ((bits & 0xAAAAAAAAu) >> 1);
  bits = ((bits & 0x33333333u) << 2) | ((bits & 0xCCCCCCCCu) >> 2);
  bits = ((bits & 0x0F0F0F0Fu) << 4) | ((bits & 0xF0F0F0F0u) >> 4);
  bits = ((bits & 0x00FF00FFu) << 8) | ((bits & 0xFF00FF00u) >> 8);
  u1 = std::fmod((i + 0.5) / n + shift1, 1.0);
  u2 = std::fmod(double(bits) * 2.3283064365386963e-10 + shift2, 1.0);
}

inline ImportanceSamples drawImportanceSamples(const IrradianceAtlas& atlas,
                                               const SamplingOptions& options) {
  if (options.samples < 1)
    throw std::invalid_argument("samples must be >= 1, not " + std::to_string(options.samples));
  ImportanceSamples out;
  const int res = atlas.resolution;
  std::optional<MipIcdf> mip;
  std::optional<RowIcdf> row;
  if (options.sampler == TexelSampler::Mipmap)
    mip.emplace(res, res, atlas.importance);
  else
    row.emplace(res, res, atlas.importance);
  const double total = mip ? mip->total() : row->total();
  if (!(total > 0))
    return out;  // no light reaches the surface: B = 0 everywhere, and nothing to divide
  util::Rng rng(options.seed);
  const double shift1 = rng.uniform(), shift2 = rng.uniform();
  const std::uint32_t n = std::uint32_t(options.samples);
  for (auto* v : {&out.x, &out.y, &out.z, &out.w[0], &out.w[1], &out.w[2]}) v->reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    double u1, u2;
    if (options.pattern == SamplePattern::Stratified)
      stratifiedPoint(i, n, shift1, shift2, u1, u2);
    else
      u1 = rng.uniform(), u2 = rng.uniform();
    const auto s = mip ? mip->sample(u1, u2) : row->sample(u1, u2);
    if (!s) continue;
    const std::size_t t = std::size_t(s->y) * std::size_t(res) + std::size_t(s->x);
    const AtlasSurface& surface = *atlas.surface;
    glm::vec3 p = surface.position[t];
    if (options.jitterInTexel)
      p += float(s->u - s->x - 0.5) * surface.dPdx[t] + float(s->v - s->y - 0.5) * surface.dPdy[t];
    out.x.push_back(p.x), out.y.push_back(p.y), out.z.push_back(p.z);
    const double scale = 1.0 / (s->probability * double(n));
    for (int c = 0; c < 3; ++c) out.w[c].push_back(float(double(atlas.power[t][c]) * scale));
  }
  return out;
}

}  // namespace lucent::atlas
