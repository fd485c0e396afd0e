#pragma once
/// @file near_field.hpp
/// @brief The samples near a shading point, integrated analytically instead of point-sampled.
///
/// The point sum B(xo) = sum_i E_i A_i Rd(|x_i - xo|) (Chang et al. 2008 Eq. 3)
/// resolves Rd only when the sample spacing is below the mean free path; a large object under a
/// sample budget has samples centimetres apart, and the nearest one, at e^{-sigma_tr r}, gives
/// nothing: a 10 m sphere came out black. Within a radius rho of xo this replaces the points by a
/// disc of the same irradiance,
///   B(xo) = sum_{|x_i - xo| > rho} E_i A_i Rd(|x_i - xo|) + E_near 2 pi int_0^rho Rd(r) r dr,
///   E_near = sum_near E_i A_i / sum_near A_i,
/// which needs only E to be smooth over rho (not Rd to be resolved), and tends to the local limit
/// B = E Rd_total (Jensen et al. 2001, Eq. 14) when the spacing is far above the mean free path.
/// Where the spacing resolves a channel's mean free path the point sum is the better quadrature
/// (superconvergent on a flat lattice, 6e-8 at half a mean free path, against 6e-3 for the disc,
/// whose rim cuts the lattice), so each channel blends from the point sum at spacing <= l_u to the
/// disc at spacing >= 4 l_u: converged results do not move.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "../optics/profile.hpp"

namespace lucent::reference {

class NearField {
 public:
  /// The near radius in sample spacings: about 16 samples of area ~0.43 spacing^2 fall inside.
  static constexpr double kRadiusInSpacings = 1.5;

  NearField() = default;
  /// Every sample, lit or not (an unlit one's area counts in E_near: a shadow edge stays sharp).
  NearField(const std::vector<glm::dvec3>& position, const std::vector<glm::dvec3>& power,
            const std::vector<double>& area, double spacing)
      : mRadius(kRadiusInSpacings * spacing),
        mPosition(position.begin(), position.end()),
        mPower(power.begin(), power.end()),
        mArea(area.begin(), area.end()) {
    if (!(mRadius > 0) || position.empty()) return;
    mOrder.resize(position.size());
    std::iota(mOrder.begin(), mOrder.end(), 0u);
    std::vector<std::uint64_t> key(position.size());
    for (std::size_t i = 0; i < position.size(); ++i) key[i] = cellKey(cellOf(position[i]));
    std::sort(mOrder.begin(), mOrder.end(),
              [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    for (std::size_t k = 0; k < mOrder.size(); ++k)
      if (mKeys.empty() || mKeys.back() != key[mOrder[k]]) {
        mKeys.push_back(key[mOrder[k]]);
        mStart.push_back(std::uint32_t(k));
      }
    mStart.push_back(std::uint32_t(mOrder.size()));
  }

  double radius() const { return mRadius; }
  std::size_t bytes() const {
    return mPosition.size() * (sizeof(glm::vec3) * 2 + sizeof(float) + sizeof(std::uint32_t)) +
           mKeys.size() * (sizeof(std::uint64_t) + sizeof(std::uint32_t));
  }

  /// What to add to the full point sum at xo: the disc integral minus the near samples' point
  /// terms (computed exactly as the sum computed them, so they cancel).
  template <class T>
  glm::dvec3 correction(const glm::dvec3& xo, const optics::Profile<T>& dipole) const {
    glm::dvec3 out(0);
    forEachNear(xo, dipole, [&](std::uint32_t i, const glm::dvec3& coefficient) {
      out += glm::dvec3(mPower[i]) * coefficient;
    });
    return out;
  }

  /// The correction as a linear map of the near samples' powers: visit(i, c) for each sample i
  /// within the radius, with the correction = sum_i power_i c_i per channel,
  /// c_i = weight (cumulative Rd(rho) / near area - Rd(r_i)). What a sum over anything linear in
  /// the power (a transport vector) applies.
  template <class T, class Visit>
  void forEachNear(const glm::dvec3& xo, const optics::Profile<T>& dipole, Visit&& visit) const {
    if (mKeys.empty()) return;
    std::vector<std::pair<std::uint32_t, double>> near;
    double area = 0;
    const glm::ivec3 c = cellOf(xo);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto at =
              std::lower_bound(mKeys.begin(), mKeys.end(), cellKey(c + glm::ivec3(dx, dy, dz)));
          if (at == mKeys.end() || *at != cellKey(c + glm::ivec3(dx, dy, dz))) continue;
          const std::size_t cell = std::size_t(at - mKeys.begin());
          for (std::uint32_t k = mStart[cell]; k < mStart[cell + 1]; ++k) {
            const std::uint32_t i = mOrder[k];
            const double r = glm::length(glm::dvec3(mPosition[i]) - xo);
            if (r > mRadius) continue;
            area += double(mArea[i]);
            near.emplace_back(i, r);
          }
        }
    if (!(area > 0)) return;
    glm::dvec3 discPerArea, weight;
    for (int ch = 0; ch < 3; ++ch) {
      const auto& channel = dipole.channel[ch];
      discPerArea[ch] = double(channel.cumulative(T(mRadius))) / area;
      // A profile singular at r = 0 (beam diffusion, Burley) is no point-sum integrand there:
      // always the disc.
      weight[ch] = channel.isPolePair() ? discWeight(double(channel.width())) : 1.0;
    }
    for (const auto& [i, r] : near) {
      glm::dvec3 coefficient;
      for (int ch = 0; ch < 3; ++ch)
        coefficient[ch] = weight[ch] * (discPerArea[ch] - double(dipole.channel[ch].rd(T(r))));
      visit(i, coefficient);
    }
  }

  /// 0 where the spacing resolves Rd (spacing <= its width w), 1 from 4 w, linear between.
  double discWeight(double width) const {
    const double spacing = mRadius / kRadiusInSpacings;
    return std::clamp((spacing / width - 1) / 3, 0.0, 1.0);
  }

 private:
  glm::ivec3 cellOf(const glm::dvec3& p) const {
    // Cells of the near radius; coordinates far beyond 2^20 cells wrap in the key, which costs
    // only extra distance tests.
    return glm::ivec3(glm::clamp(glm::floor(p / mRadius), glm::dvec3(-1e9), glm::dvec3(1e9)));
  }
  static std::uint64_t cellKey(const glm::ivec3& c) {
    const auto part = [](int v) { return std::uint64_t(std::uint32_t(v) & 0x1fffffu); };
    return part(c.x) | part(c.y) << 21 | part(c.z) << 42;
  }

  double mRadius = 0;
  std::vector<glm::vec3> mPosition, mPower;  // float: 32 bytes a sample with the area and order
  std::vector<float> mArea;
  std::vector<std::uint32_t> mOrder;
  std::vector<std::uint64_t> mKeys;
  std::vector<std::uint32_t> mStart;
};

}  // namespace lucent::reference
