#pragma once
/// @file hero_channel_weight.hpp
/// @brief Channel-aware sampling of RGB media: each path draws its distances with one "hero" channel,
/// chosen uniformly, and is weighted by one-sample MIS (balance heuristic) over the three channels:
/// value = f / ((1/3) sum_c p_c), where f is the path contribution per channel and p_c the path's pdf had
/// channel c been the hero. Tracking the whole-path pdfs (not a per-step ratio) bounds the weight by 3
/// however different the channels are (skin's blue sigma_t is 3x its red), so no channel's estimate
/// blows up. Both are rescaled by one scalar each step: only their ratio matters.
#include <algorithm>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace lucent::reference {

struct HeroChannelWeight {
  glm::dvec3 f{1};  ///< path contribution per channel
  glm::dvec3 p{1};  ///< path pdf per would-be hero channel

  void scale(const glm::dvec3& contribution, const glm::dvec3& pdf) {
    f *= contribution;
    p *= pdf;
    const double m = std::max(p.x, std::max(p.y, p.z));
    if (m > 0) f /= m, p /= m;  // keeps the numbers near 1; the ratio is unchanged
  }
  /// Contribution only (a deterministic factor, e.g. an estimated transmittance or a selection 1/q).
  void scale(const glm::dvec3& contribution) { f *= contribution; }

  glm::dvec3 value() const {
    const double meanPdf = (p.x + p.y + p.z) / 3;
    return meanPdf > 0 ? f / meanPdf : glm::dvec3(0);
  }
  /// The estimate of a path joined from two subpaths sampled with the same hero channel.
  static glm::dvec3 joined(const HeroChannelWeight& a, const HeroChannelWeight& b, const glm::dvec3& link) {
    const glm::dvec3 p = a.p * b.p;
    const double meanPdf = (p.x + p.y + p.z) / 3;
    return meanPdf > 0 ? a.f * b.f * link / meanPdf : glm::dvec3(0);
  }
};

}  // namespace lucent::reference
