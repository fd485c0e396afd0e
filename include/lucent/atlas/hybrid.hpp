#pragma once
/// @file hybrid.hpp
/// @brief The hybrid method (Chang et al. 2008 Sec. 4): B = B_l + B_g with
/// B_l = int E Rd Wl dA by translucent shadow maps and B_g = int E Rd Wg dA by texture-space
/// importance sampling. Also the plain translucent-shadow-map method (f = Rd, no split) as a
/// baseline.
#include <memory>
#include <vector>

#include "../optics/dipole_lut.hpp"
#include "hybrid_split.hpp"
#include "translucent_shadow_map.hpp"
#include "tsis_evaluator.hpp"

namespace lucent::atlas {

/// Rd Wl and Rd Wg as tables on [0, rMax] (the same kind of 1-D texture as Rd itself).
struct HybridProfiles {
  double rp = 0, k = kHybridK;
  optics::RadialTable<float> local, global;

  HybridProfiles(const optics::Profile<double>& d, double rp_, double rMax, double k_ = kHybridK)
      : rp(rp_),
        k(k_),
        local(
            [&](float r) {
              return optics::Rgb<float>(d.rd(double(r)) * localWeight(double(r), rp_, k_));
            },
            float(rMax), {}, optics::Rgb<float>(d.regularFrom())),
        global(
            [&](float r) {
              return optics::Rgb<float>(d.rd(double(r)) * globalWeight(double(r), rp_, k_));
            },
            float(rMax), {}, optics::Rgb<float>(d.regularFrom())) {}
};

/// The local term: one translucent shadow map per light, each filtered with the same ring filter.
class LocalTermEvaluator {
 public:
  LocalTermEvaluator(std::vector<TranslucentShadowMap> maps, RingFilter ring,
                     const optics::RadialTable<float>& profile, float eta)
      : mMaps(std::move(maps)), mRing(std::move(ring)), mProfile(profile), mFt(eta) {}

  glm::dvec3 radiosity(const glm::dvec3& xo) const {
    glm::dvec3 b(0);
    for (const auto& m : mMaps) b += m.filterTable(xo, mRing, mProfile);
    return b;
  }
  double fresnelOverPi(double cosOut) const { return double(mFt(float(cosOut))) / optics::kPi; }
  glm::dvec3 radiance(const glm::dvec3& xo, double cosOut) const {
    return radiosity(xo) * fresnelOverPi(cosOut);
  }
  const RingFilter& ring() const { return mRing; }

 private:
  std::vector<TranslucentShadowMap> mMaps;
  RingFilter mRing;
  reference::PlanarRadialTable mProfile;
  optics::FtTable<float> mFt;
};

/// B = B_l + B_g.
class HybridEvaluator {
 public:
  HybridEvaluator(const LocalTermEvaluator& local, const TsisEvaluator& global)
      : mLocal(local), mGlobal(global) {}
  glm::dvec3 radiosity(const glm::dvec3& xo) const {
    return mLocal.radiosity(xo) + mGlobal.radiosity(xo);
  }
  double fresnelOverPi(double cosOut) const { return mGlobal.fresnelOverPi(cosOut); }
  glm::dvec3 radiance(const glm::dvec3& xo, double cosOut) const {
    return radiosity(xo) * fresnelOverPi(cosOut);
  }

 private:
  const LocalTermEvaluator& mLocal;
  const TsisEvaluator& mGlobal;
};

}  // namespace lucent::atlas
