#pragma once
/// @file hybrid_split.hpp
/// @brief The hybrid method's split of Rd into a local and a global term (Chang et al. 2008
/// Sec. 4.1): Rd = Rd Wl + Rd Wg with
///   Wl(r) = 1 - 0.5 e^{(r - Rp) K}   for r <= Rp,      Wl(r) = 0.5 e^{-(r - Rp) K}   for r > Rp,
///   Wg = 1 - Wl,  K = 1.5 (per mm).
/// The extracted paper text prints e^{-(r-Rp)K} in both branches, which makes Wl negative for r <
/// Rp - ln2/K; the form above is the continuous one (Wl = 0.5 at Rp, Wl(0) ~ 1, Wl -> 0 far away)
/// that Fig. 3 shows. Rp is the largest r, over the channels, where the importance Rd(r) 2 pi r
/// falls to the user's bound c (Fig. 4).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "../optics/profile.hpp"

namespace lucent::atlas {

inline constexpr double kHybridK = 1.5;  ///< the paper's constant K (mm^-1)

/// Wl(r): the local share of Rd at distance r.
inline double localWeight(double r, double rp, double k = kHybridK) {
  return r <= rp ? 1.0 - 0.5 * std::exp((r - rp) * k) : 0.5 * std::exp(-(r - rp) * k);
}
inline double globalWeight(double r, double rp, double k = kHybridK) {
  return 1.0 - localWeight(r, rp, k);
}

/// Importance of distance r for one channel: Rd(r) 2 pi r (mm^-1).
/// @tparam Channel optics::DipoleChannel or optics::ProfileChannel (rd, scatters, reach).
template <class Channel>
double importance(const Channel& ch, double r) {
  return ch.rd(r) * 2 * optics::kPi * r;
}

/// Largest r with importance(r) = c in one channel, or 0 if the importance never reaches c.
/// Terminates for every material: past its peak the importance falls at least as 1/r^2 (sigma_a =
/// 0).
template <class Channel>
double importanceRadius(const Channel& ch, double c) {
  if (!(c > 0)) throw std::invalid_argument("importance bound c must be > 0");
  if (!ch.scatters()) return 0;
  // The importance rises to one peak (on the scale of z_r, well inside the profile's reach) and
  // then falls: the last crossing lies beyond the peak. Bracket it by doubling outwards from the
  // peak, then bisect.
  const double scanEnd = ch.reach();
  double lo = 0, peak = 0;
  for (int i = 1; i <= 400; ++i) {
    const double r = scanEnd * i / 400.0, f = importance(ch, r);
    if (f > peak) peak = f, lo = r;
  }
  if (peak < c) return 0;
  double hi = 2 * lo;
  for (int i = 0; i < 200 && importance(ch, hi) >= c; ++i) lo = hi, hi *= 2;
  if (importance(ch, hi) >= c) return hi;  // unreachable for finite c; bounded all the same
  for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (importance(ch, mid) >= c ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

/// Rp: the largest importance radius over the three channels (0: nothing is local, all global).
inline double hybridRp(const optics::Profile<double>& d, double c) {
  double rp = 0;
  for (const auto& ch : d.channel) rp = std::max(rp, importanceRadius(ch, c));
  return rp;
}

}  // namespace lucent::atlas
