#pragma once
/// @file hero_channel_weight.hpp
/// @brief Channel-aware sampling of RGB media: each path draws its distances with one "hero"
/// channel, chosen with probability P_c, and is weighted by one-sample MIS (balance heuristic) over
/// the three channels: value = f / sum_c P_c p_c, where f is the path contribution per channel and
/// p_c the path's pdf had channel c been the hero (Wilkie et al. 2014). Tracking the whole-path
/// pdfs (not a per-step ratio) bounds the weight by 1 / min P_c however different the channels
/// are (skin's blue sigma_t is 3x its red), so no channel's estimate blows up. Both are rescaled by
/// one scalar each step: only their ratio matters.
#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace lucent::reference {

struct HeroChannelWeight {
  glm::dvec3 f{1};             ///< path contribution per channel
  glm::dvec3 p{1};             ///< path pdf per would-be hero channel
  glm::dvec3 choice{1.0 / 3};  ///< P_c: the probability of each channel being the hero

  void scale(const glm::dvec3& contribution, const glm::dvec3& pdf) {
    f *= contribution;
    p *= pdf;
    const double m = std::max(p.x, std::max(p.y, p.z));
    if (m > 0) f /= m, p /= m;  // keeps the numbers near 1; the ratio is unchanged
  }
  /// Contribution only (a deterministic factor, e.g. an estimated transmittance or a selection
  /// 1/q).
  void scale(const glm::dvec3& contribution) { f *= contribution; }

  /// Draws the hero channel for u uniform in [0, 1).
  int pickHero(double u) const { return u < choice.x ? 0 : (u < choice.x + choice.y ? 1 : 2); }

  glm::dvec3 value() const {
    const double meanPdf = glm::dot(choice, p);
    return meanPdf > 0 ? f / meanPdf : glm::dvec3(0);
  }
  /// The estimate of a path joined from two subpaths sampled with the same hero channel (and the
  /// same choice probabilities).
  static glm::dvec3 joined(const HeroChannelWeight& a, const HeroChannelWeight& b,
                           const glm::dvec3& link) {
    const glm::dvec3 p = a.p * b.p;
    const double meanPdf = glm::dot(a.choice, p);
    return meanPdf > 0 ? a.f * b.f * link / meanPdf : glm::dvec3(0);
  }
};

}  // namespace lucent::reference
