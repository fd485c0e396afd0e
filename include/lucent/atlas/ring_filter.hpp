#pragma once
/// @file ring_filter.hpp
/// @brief The circular filter of Chang et al. 2008 Sec. 4.2: L*C + 1 samples, one at the
/// centre and C on each of L concentric rings whose radii follow the importance f(r) 2 pi r of the
/// filtered profile f (Rd Wl for the hybrid's local term, Rd for a plain translucent shadow map),
/// as Mertens et al. 2003 chose radii.
///
/// The radial axis is cut into L + 1 strata of equal importance; the centre sample stands for the
/// innermost disc and ring k for stratum k, at the radius where the importance CDF reaches the
/// stratum's middle. A sample estimates its stratum's integral by the ratio estimator
///   int_stratum rho f dA  ~=  M_k,c * rho(x) f_c(|x - x_o|) / f_c(r_k),
///   M_k,c = int_stratum f_c 2 pi r dr,
/// which is exact on a flat, uniformly lit surface (|x - x_o| = r_k) and, f being decreasing, never
/// amplifies a sample (|x - x_o| >= r_k). The centre sample stands for the whole disc [0, R_0],
/// where r_0 = 0 is no representative radius for a profile singular at 0 (pbd, Burley: f(0) is
/// their held core, so f(d) / f(0) drops the disc's mass, measured 10 % of blue on a skin sphere).
/// Its estimator is the disc seen from a distance d off its plane, exact for a flat disc:
///   M_0,c * T_c(d),  T_c(d) = (C_c(sqrt(R_0^2 + d^2)) - C_c(d)) / C_c(R_0),
/// with C_c(r) = int_0^r f_c 2 pi r dr (centreTransfer; T(0) = 1 for every profile).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "../optics/constants.hpp"

namespace lucent::atlas {

struct RingFilter {
  int rings = 0, perRing = 0;
  std::vector<double> radius;         ///< [0] = 0 (centre), then the L ring radii (mm)
  std::vector<glm::dvec3> mass;       ///< M_k per channel, same indexing
  std::vector<glm::dvec3> profileAt;  ///< f_c(radius[k])
  double outerRadius = 0;             ///< the filter's extent: the strata cover [0, outerRadius]
  double innerRadius = 0;             ///< R_0, the outer edge of the centre's disc
  /// C_c on r_j = domain (j / J)^2 (the grid the radii were placed on), for centreTransfer.
  std::vector<glm::dvec3> cumulative;
  double domain = 0;
  /// The ring taps, ring by ring, C per ring: the offset from x_o's projection at turn 0 (mm, on
  /// the map's two axes; ring k's spokes start at k golden angles, so rings do not line up), and
  /// ratioFactor of the tap. Computed once, so no per-point work repeats them.
  std::vector<glm::dvec2> tapOffset;
  std::vector<glm::dvec3> tapFactor;
  int sampleCount() const { return rings * perRing + 1; }
  /// True when the taps match the rings (makeRingFilter fills them; a hand-edited filter may not).
  bool tapsPlaced() const {
    return tapOffset.size() == std::size_t(rings) * std::size_t(perRing) &&
           tapFactor.size() == tapOffset.size();
  }
  /// The stratum of ring tap j (1..L).
  std::size_t tapStratum(std::size_t j) const { return j / std::size_t(perRing) + 1; }

  /// C_c(r), linear between the grid's nodes; the total beyond the domain.
  glm::dvec3 cumulativeAt(double r) const {
    if (cumulative.size() < 2 || !(r > 0)) return glm::dvec3(0);
    const double last = double(cumulative.size() - 1);
    const double u = std::sqrt(r / domain) * last;
    if (!(u < last)) return cumulative.back();
    const std::size_t j = std::size_t(u);
    const double t = u - double(j);
    return cumulative[j] * (1 - t) + cumulative[j + 1] * t;
  }
  /// T_c(d), the centre sample's transfer at distance d (file comment): 1 at d = 0.
  glm::dvec3 centreTransfer(double d) const {
    const glm::dvec3 disc = cumulativeAt(innerRadius);
    const glm::dvec3 seen = cumulativeAt(std::hypot(innerRadius, d)) - cumulativeAt(d);
    glm::dvec3 t(0);
    for (int c = 0; c < 3; ++c) t[c] = disc[c] > 0 ? std::clamp(seen[c] / disc[c], 0.0, 1.0) : 0.0;
    return t;
  }
  /// A tap of stratum k holding `value` = rho f(d) (or rho times any kernel the filter stands for):
  /// its share of the stratum's mass times value / f(r_k), the ratio estimator (file comment).
  glm::dvec3 tapEstimate(std::size_t k, double share, const glm::dvec3& value) const {
    return ratioFactor(k, share) * value;
  }
  /// share M_k,c / f_c(r_k) per channel, 0 where f_c(r_k) = 0.
  glm::dvec3 ratioFactor(std::size_t k, double share) const {
    glm::dvec3 e(0);
    for (int c = 0; c < 3; ++c)
      if (profileAt[k][c] > 0) e[c] = share * mass[k][c] / profileAt[k][c];
    return e;
  }
};

namespace detail {
/// Nodes of the cumulative grid: r_j = domain (j / J)^2, dense near 0 where f peaks.
constexpr int kRingGrid = 8192;
inline double ringGridRadius(int j, double domain) {
  const double s = double(j) / kRingGrid;
  return domain * s * s;
}

/// C_c(r_j) = int_0^{r_j} f_c 2 pi r dr per channel, by the trapezoid rule on the grid.
template <class Profile>
std::vector<glm::dvec3> cumulativeGrid(const Profile& profile, double domain) {
  std::vector<glm::dvec3> cum(kRingGrid + 1, glm::dvec3(0));
  glm::dvec3 prev(0);
  for (int j = 1; j <= kRingGrid; ++j) {
    const double r = ringGridRadius(j, domain), rPrev = ringGridRadius(j - 1, domain);
    const glm::dvec3 cur = profile(r) * (2 * optics::kPi * r);
    cum[std::size_t(j)] = cum[std::size_t(j) - 1] + 0.5 * (prev + cur) * (r - rPrev);
    prev = cur;
  }
  return cum;
}

/// The channels' CDFs averaged (each channel weighs equally in placing the radii); empty when no
/// channel scatters.
inline std::vector<double> combinedCdf(const std::vector<glm::dvec3>& cum) {
  const glm::dvec3 total = cum.back();
  int active = 0;
  for (int c = 0; c < 3; ++c) active += total[c] > 0;
  if (active == 0) return {};
  std::vector<double> combined(cum.size(), 0.0);
  for (std::size_t j = 0; j < cum.size(); ++j)
    for (int c = 0; c < 3; ++c)
      if (total[c] > 0) combined[j] += cum[j][c] / total[c] / active;
  return combined;
}

/// The radius where the combined CDF reaches q (linear between grid nodes).
inline double radiusAtFraction(const std::vector<double>& combined, double q, double domain) {
  const auto it = std::lower_bound(combined.begin(), combined.end(), q);
  if (it == combined.begin()) return 0.0;
  if (it == combined.end()) return domain;
  const int j = int(it - combined.begin());
  const double span = combined[std::size_t(j)] - combined[std::size_t(j) - 1];
  const double f = span > 0 ? (q - combined[std::size_t(j) - 1]) / span : 0.0;
  const double lo = ringGridRadius(j - 1, domain);
  return lo + f * (ringGridRadius(j, domain) - lo);
}

/// Fills the filter's tap offsets and factors from its radii and masses.
inline void placeTaps(RingFilter& filter) {
  filter.tapOffset.clear();
  filter.tapFactor.clear();
  for (int k = 1; k <= filter.rings; ++k)
    for (int c = 0; c < filter.perRing; ++c) {
      const double phi = optics::kGoldenAngle * k + 2 * optics::kPi * c / filter.perRing;
      const double r = filter.radius[std::size_t(k)];
      filter.tapOffset.emplace_back(r * std::cos(phi), r * std::sin(phi));
      filter.tapFactor.push_back(filter.ratioFactor(std::size_t(k), 1.0 / filter.perRing));
    }
}
}  // namespace detail

/// @param profile callable double -> glm::dvec3, f(r) >= 0 and non-increasing; @param domain the
/// largest distance considered (the object's diagonal); @param coverage the share of the importance
/// the strata cover (the rest of the far tail is dropped: it belongs to the global term or is
/// negligible).
template <class Profile>
RingFilter makeRingFilter(const Profile& profile, int rings, int perRing, double domain,
                          double coverage = 0.9995) {
  if (rings < 1 || perRing < 1)
    throw std::invalid_argument("ring filter needs L >= 1 rings of C >= 1 samples");
  if (!(domain > 0)) throw std::invalid_argument("ring filter domain must be > 0");
  RingFilter filter;
  filter.rings = rings;
  filter.perRing = perRing;
  filter.domain = domain;
  filter.cumulative = detail::cumulativeGrid(profile, domain);
  const std::vector<double> combined = detail::combinedCdf(filter.cumulative);
  if (combined.empty()) {  // nothing scatters: an empty filter (every mass 0)
    filter.radius.assign(std::size_t(rings) + 1, 0.0);
    filter.mass.assign(std::size_t(rings) + 1, glm::dvec3(0));
    filter.profileAt.assign(std::size_t(rings) + 1, glm::dvec3(0));
    detail::placeTaps(filter);
    return filter;
  }
  const auto inverse = [&](double q) { return detail::radiusAtFraction(combined, q, domain); };
  const double cover = std::clamp(coverage, 0.5, 1.0);
  filter.outerRadius = inverse(cover);
  const int strata = rings + 1;
  for (int k = 0; k < strata; ++k) {
    const double lo = inverse(cover * k / strata), hi = inverse(cover * (k + 1) / strata);
    const double rk = k == 0 ? 0.0 : inverse(cover * (k + 0.5) / strata);
    filter.radius.push_back(rk);
    if (k == 0) filter.innerRadius = hi;
    filter.mass.push_back(filter.cumulativeAt(hi) - filter.cumulativeAt(lo));
    filter.profileAt.push_back(profile(rk));
  }
  detail::placeTaps(filter);
  return filter;
}

}  // namespace lucent::atlas
