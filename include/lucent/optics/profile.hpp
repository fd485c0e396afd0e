#pragma once
/// @file profile.hpp
/// @brief The diffusion profile every dipole technique sums: one value type over the models of this
/// core, chosen by name (the `profile` knob). Each model gives R(r) (mm^-2), its exact radial
/// cumulative 2 pi int_0^rho R r dr, its total diffuse reflectance, the radius holding a fraction
/// of the total (the inverse CDF), and how its exitance becomes radiance.
///
/// Radiance: the classic dipole keeps Jensen et al. 2001's L = Ft(w) B / pi (Eq. 5, the convention
/// every figure of this project before profiles was measured in). The other models' R is the
/// exitance that crosses the boundary, so L = Ft(w) B / (pi c), c = 1 - 2 C_1(external)
/// (fresnel_moments.hpp), which makes the radiance carry exactly B (Habel et al. 2013 Sec. 4;
/// pbrt's Sw does the same).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>

#include "beam_diffusion_table.hpp"
#include "burley.hpp"
#include "dipole.hpp"
#include "dipole_lut.hpp"
#include "fresnel_moments.hpp"
#include "rgb.hpp"

namespace lucent::optics {

enum class ProfileModel { Dipole, BetterDipole, BeamDiffusion, Burley, BurleyDiffuse };

struct ProfileModelInfo {
  ProfileModel model;
  std::string_view name;
  std::string_view summary;
};

/// The models and their names: the one list the knob, the CLI and the docs read.
inline constexpr std::array<ProfileModelInfo, 5> kProfileModels{{
    {ProfileModel::Dipole, "dipole",
     "classic dipole (Jensen et al. 2001): flux of a real and a virtual source"},
    {ProfileModel::BetterDipole, "better-dipole",
     "better dipole (d'Eon 2012): Grosjean's D, exact Fresnel moments, fluence and flux"},
    {ProfileModel::BeamDiffusion, "pbd",
     "photon beam diffusion (Habel et al. 2013): better dipoles along the beam plus its single "
     "scattering, tabulated; its total exceeds 1 near zero absorption (1.03 at eta 1.3)"},
    {ProfileModel::Burley, "burley",
     "Christensen-Burley normalized diffusion, searchlight fit, albedo from beam diffusion"},
    {ProfileModel::BurleyDiffuse, "burley-diffuse",
     "Christensen-Burley normalized diffusion, diffuse-surface fit, albedo from beam diffusion"},
}};

inline const ProfileModelInfo& profileModelInfo(ProfileModel m) {
  for (const auto& info : kProfileModels)
    if (info.model == m) return info;
  return kProfileModels[0];
}

/// The model called `name`; throws std::invalid_argument listing the names otherwise.
inline ProfileModel profileModelNamed(std::string_view name) {
  for (const auto& info : kProfileModels)
    if (info.name == name) return info.model;
  std::string names;
  for (const auto& info : kProfileModels)
    names += (names.empty() ? "" : ", ") + std::string(info.name);
  throw std::invalid_argument("unknown profile '" + std::string(name) + "'; the profiles are " +
                              names);
}

/// The two models with a closed-form R(r) (a real and a virtual point source).
constexpr bool isPolePair(ProfileModel m) {
  return m == ProfileModel::Dipole || m == ProfileModel::BetterDipole;
}

/// One channel of a profile.
template <class T>
struct ProfileChannel {
  ProfileModel model = ProfileModel::Dipole;
  DipoleChannel<T> poles;        ///< Dipole, BetterDipole
  BeamDiffusionChannel<T> beam;  ///< BeamDiffusion
  BurleyChannel<T> burley;       ///< Burley, BurleyDiffuse
  T meanFreePathMm = 1;          ///< 1/sigma_t' whatever the model (the spacing the sums resolve)

  bool isPolePair() const { return optics::isPolePair(model); }
  /// f applied to the model's own channel: the one place the model is dispatched on.
  template <class F>
  auto visit(const F& f) const {
    if (isPolePair()) return f(poles);
    return model == ProfileModel::BeamDiffusion ? f(beam) : f(burley);
  }
  bool scatters() const {
    return visit([](const auto& c) { return c.scatters(); });
  }
  T rd(T r) const {
    return visit([r](const auto& c) { return c.rd(r); });
  }
  T cumulative(T rho) const {
    return visit([rho](const auto& c) { return c.cumulative(rho); });
  }
  T total() const {
    return visit([](const auto& c) { return c.total(); });
  }
  T meanFreePath() const { return meanFreePathMm; }
  /// The length R falls off over (what a point sum must resolve).
  T width() const {
    return visit([](const auto& c) { return c.width(); });
  }
  /// A distance beyond the peak of R(r) 2 pi r.
  T reach() const {
    return visit([](const auto& c) { return c.reach(); });
  }
  /// The radius within which `fraction` of the total leaves (the inverse of the radial CDF), by
  /// bisection on the exact cumulative; 0 for a channel that does not scatter.
  T radiusHolding(T fraction) const {
    const T total_ = total();
    if (!(total_ > T(0)) || !(fraction > T(0))) return T(0);
    const T target = std::min(fraction, T(1)) * total_;
    T lo = 0, hi = meanFreePathMm;
    for (int i = 0; i < 200 && cumulative(hi) < target; ++i) lo = hi, hi *= 2;
    for (int i = 0; i < 200 && hi - lo > T(1e-7) * hi; ++i) {
      const T mid = T(0.5) * (lo + hi);
      (cumulative(mid) < target ? lo : hi) = mid;
    }
    return T(0.5) * (lo + hi);
  }

  static ProfileChannel make(ProfileModel model, T sigmaA, T sigmaSPrime, T eta, double c1,
                             double c2) {
    ProfileChannel c;
    c.model = model;
    const T st = sigmaA + sigmaSPrime;
    c.meanFreePathMm = st > T(0) ? T(1) / st : T(1);
    switch (model) {
      case ProfileModel::Dipole:
        c.poles = DipoleChannel<T>::make(sigmaA, sigmaSPrime, eta);
        break;
      case ProfileModel::BetterDipole:
        c.poles = DipoleChannel<T>::makeBetter(sigmaA, sigmaSPrime, T(c1), T(c2));
        break;
      case ProfileModel::BeamDiffusion:
        c.beam = BeamDiffusionChannel<T>::make(sigmaA, sigmaSPrime, eta, c1, c2);
        break;
      case ProfileModel::Burley:
      case ProfileModel::BurleyDiffuse: {
        const auto beam = BeamDiffusionChannel<T>::make(sigmaA, sigmaSPrime, eta, c1, c2);
        const BurleyFit fit =
            model == ProfileModel::Burley ? BurleyFit::Searchlight : BurleyFit::DiffuseSurface;
        // A passive surface's albedo is at most 1; beam diffusion's total exceeds it near zero
        // absorption (beam_diffusion.hpp), so it is held there.
        c.burley = BurleyChannel<T>::make(std::min(beam.total(), T(1)), c.meanFreePathMm, fit);
        break;
      }
    }
    return c;
  }
};

/// A profile in three channels.
template <class T>
struct Profile {
  ProfileChannel<T> channel[kChannels];
  ProfileModel model = ProfileModel::Dipole;
  T eta = T(1.3);
  T exitScale =
      1;  ///< 1/c for the exitance models, 1 for the classic dipole (see the file comment)

  Profile() = default;
  /// The classic dipole as a profile (what code written for the dipole passes).
  Profile(const Dipole<T>& d) : eta(d.eta) {  // NOLINT: implicit on purpose
    for (int c = 0; c < kChannels; ++c) {
      channel[c].model = ProfileModel::Dipole;
      channel[c].poles = d.channel[c];
      channel[c].meanFreePathMm = d.channel[c].zr;
    }
  }

  static Profile make(ProfileModel model, const Rgb<T>& sigmaA, const Rgb<T>& sigmaSPrime, T eta) {
    Profile p;
    p.model = model;
    p.eta = eta;
    const double c1 = internalFresnelMoment(1, double(eta));
    const double c2 = internalFresnelMoment(2, double(eta));
    for (int c = 0; c < kChannels; ++c)
      p.channel[c] = ProfileChannel<T>::make(model, sigmaA[c], sigmaSPrime[c], eta, c1, c2);
    p.exitScale = model == ProfileModel::Dipole ? T(1) : T(1 / exitNormalisation(double(eta)));
    return p;
  }

  bool isPolePair() const { return channel[0].isPolePair(); }
  Rgb<T> rd(T r) const { return {channel[0].rd(r), channel[1].rd(r), channel[2].rd(r)}; }
  Rgb<T> cumulative(T rho) const {
    return {channel[0].cumulative(rho), channel[1].cumulative(rho), channel[2].cumulative(rho)};
  }
  Rgb<T> total() const { return {channel[0].total(), channel[1].total(), channel[2].total()}; }
  /// The largest radius over the channels within which `fraction` of each channel's total leaves:
  /// how far the profile carries light (the planner's reach, the diffuse-BRDF limit's range).
  T largestRadiusHolding(T fraction) const {
    return std::max({channel[0].radiusHolding(fraction), channel[1].radiusHolding(fraction),
                     channel[2].radiusHolding(fraction)});
  }
  /// Smallest mean free path over the channels that scatter.
  T minMeanFreePath() const {
    T m = std::numeric_limits<T>::infinity();
    for (const auto& c : channel)
      if (c.scatters() && c.meanFreePath() < m) m = c.meanFreePath();
    return m;
  }
  /// Per channel, where the profile stops being a regularised singularity: 0 for the pole pairs
  /// (finite at r = 0); for the others 1e-3 of the channel's mean free path. Beam diffusion
  /// (R_ss ~ 1/r) and Burley (1/r) hold their value constant below 1e-4 of their scale, and a 1/r
  /// profile leaves at most 0.5 % of its light inside this radius (measured over the materials,
  /// tests/unit/test_dipole_lut.cpp). Tables state their bound from here on (RadialTable).
  Rgb<T> regularFrom() const {
    Rgb<T> r(0);
    for (int c = 0; c < kChannels; ++c)
      if (!isPolePair() && channel[c].scatters()) r[c] = T(1e-3) * channel[c].meanFreePath();
    return r;
  }
  /// The pole pairs' fields (the classic or the better dipole, with C_E and C_phi / D), for code
  /// that evaluates their closed form (the truth's kernel, the GPU pass).
  Dipole<T> poles() const {
    Dipole<T> d;
    d.eta = eta;
    for (int c = 0; c < kChannels; ++c) d.channel[c] = channel[c].poles;
    return d;
  }
};

/// The profile's radial table on [0, rMax] (values of the P-precision profile stored as T), with
/// RadialTable's bound from regularFrom on: the one table tsis (CPU and GPU), tsm and the truth's
/// sum look up.
template <class T, class P>
RadialTable<T> radialTable(const Profile<P>& profile, T rMax, RdTableBound<T> bound = {}) {
  return RadialTable<T>([&profile](T r) { return Rgb<T>(profile.rd(P(r))); }, rMax, bound,
                        Rgb<T>(profile.regularFrom()));
}

}  // namespace lucent::optics
