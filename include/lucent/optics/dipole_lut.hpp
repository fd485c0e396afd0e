#pragma once
/// @file dipole_lut.hpp
/// @brief Rd(r) tabulated on [0, rMax] for fast evaluation (section 3 of Chang et al. 2008
/// stores Rd as a 1-D texture over the normalised diagonal), with a bounded, verified error.
///
/// Nodes sit at r_i = rMax (i/(N-1))^2, dense near r = 0 where Rd is sharply peaked on the scale
/// z_r, and values are linearly interpolated, exactly as a GPU 1-D texture lookup on u =
/// sqrt(r/rMax) does. The node count doubles until the error at every interval midpoint is within
/// half the requested bound.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "dipole.hpp"

namespace lucent::optics {

/// @brief Error bound of a tabulated profile, per channel on [r0, rMax] with r0 the channel's
/// regularFrom (0 for a profile finite at r = 0). Where Rd(r) >= floor * Rd(r0): |Rd_lut - Rd| <=
/// relTol * Rd(r). Elsewhere: |Rd_lut - Rd| <= relTol * floor * Rd(r0), i.e. the far tail is
/// bounded in absolute terms (it is below floor of the peak anyway).
template <class T>
struct RdTableBound {
  T relTol = T(1e-3);
  T floor = T(1e-6);
};

/// A radial profile f(r) (three channels) tabulated on [0, rMax] with the bound above, taking
/// Rd(regularFrom) as the peak the floor is relative to. Rd itself (RdTable) and the hybrid
/// method's weighted profiles Rd Wl and Rd Wg share it, so every profile the renderer looks up
/// obeys one stated bound. A profile singular at r = 0 (Profile::regularFrom) is held constant in a
/// tiny core by its model; there the bound is not asked for (the kink where the hold ends would
/// take 2^20 nodes to interpolate to 1e-3) and the table lies between the node values.
template <class T>
class RadialTable {
 public:
  /// @param profile callable T -> Rgb<T>, finite and >= 0 on [0, rMax]; @param rMax the largest
  /// distance looked up (mm), e.g. the object's diagonal. Beyond rMax lookups return 0. @param
  /// regularFrom where the bound starts, per channel (Profile::regularFrom; 0 for a profile finite
  /// at 0).
  template <class Profile>
  RadialTable(const Profile& profile, T rMax, RdTableBound<T> bound = {},
              Rgb<T> regularFrom = Rgb<T>(0))
      : mRMax(rMax), mRegularFrom(regularFrom), mBound(bound) {
    if (!(rMax > T(0)) || !std::isfinite(double(rMax)))
      throw std::invalid_argument("RdTable: rMax must be positive and finite");
    for (std::size_t n = 64;; n *= 2) {
      build(profile, n);
      if (meetsBound(profile) || n >= kMaxNodes) break;
    }
  }

  /// Interpolated f(r) for all channels; 0 beyond rMax.
  Rgb<T> operator()(T r) const {
    if (!(r >= T(0)) || r > mRMax) return Rgb<T>(0);
    const T u = std::sqrt(r / mRMax) * T(mValues.size() - 1);
    const std::size_t i = std::min<std::size_t>(std::size_t(u), mValues.size() - 2);
    const T t = u - T(i);
    return mValues[i] * (T(1) - t) + mValues[i + 1] * t;
  }

  std::size_t size() const { return mValues.size(); }
  T rMax() const { return mRMax; }
  Rgb<T> regularFrom() const { return mRegularFrom; }
  const RdTableBound<T>& bound() const { return mBound; }
  /// True when the node budget ran out before the bound was met (the bound then does not hold).
  bool saturated() const { return mSaturated; }
  /// The node values, channel-interleaved, for upload as a 1-D texture indexed by sqrt(r/rMax).
  const std::vector<Rgb<T>>& values() const { return mValues; }

 private:
  static constexpr std::size_t kMaxNodes = std::size_t(1) << 20;

  T nodeRadius(std::size_t i, std::size_t n) const {
    const T s = T(i) / T(n - 1);
    return mRMax * s * s;
  }

  template <class Profile>
  void build(const Profile& profile, std::size_t n) {
    mValues.resize(n);
    for (std::size_t i = 0; i < n; ++i) mValues[i] = profile(nodeRadius(i, n));
  }

  template <class Profile>
  bool meetsBound(const Profile& profile) {
    const std::size_t n = mValues.size();
    Rgb<T> peak;
    for (int c = 0; c < kChannels; ++c) peak[c] = profile(mRegularFrom[c])[c];
    for (std::size_t i = 0; i + 1 < n; ++i) {
      // Midpoint in the table's own coordinate u, where linear interpolation errs the most.
      const T s = (T(i) + T(0.5)) / T(n - 1);
      const T r = mRMax * s * s;
      const Rgb<T> exact = profile(r);
      const Rgb<T> approx = (mValues[i] + mValues[i + 1]) * T(0.5);
      for (int c = 0; c < kChannels; ++c) {
        if (nodeRadius(i + 1, n) < mRegularFrom[c]) continue;  // wholly inside the held core
        // Half the bound at the midpoint leaves room for the rest of the interval, where the error
        // of linear interpolation of a non-quadratic function can exceed the midpoint's.
        const T allowed = T(0.5) * mBound.relTol * std::max(exact[c], mBound.floor * peak[c]);
        if (std::abs(approx[c] - exact[c]) > allowed) {
          mSaturated = n >= kMaxNodes;
          return false;
        }
      }
    }
    mSaturated = false;
    return true;
  }

  T mRMax;
  Rgb<T> mRegularFrom;
  RdTableBound<T> mBound;
  std::vector<Rgb<T>> mValues;
  bool mSaturated = false;
};

/// Rd(r) of a dipole, tabulated.
template <class T>
class RdTable : public RadialTable<T> {
 public:
  RdTable(const Dipole<T>& dipole, T rMax, RdTableBound<T> bound = {})
      : RadialTable<T>([&dipole](T r) { return dipole.rd(r); }, rMax, bound) {}
};

}  // namespace lucent::optics
