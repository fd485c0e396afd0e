#pragma once
/// @file fresnel_table.hpp
/// @brief Ft(eta, w_o) as a 1-D table over cos(theta_o) (Chang et al. 2008 Sec. 3 stores
/// it as a 1-D texture indexed by n.w_o). Linear interpolation; 256 nodes keep the error below 1e-4
/// for every eta in [kEtaMin, kEtaMax] except within a node of the critical angle's kink (eta < 1 never
/// occurs here: light leaves the denser medium, which the dipole folds into Ft(eta) as in Eq. 2).
#include <algorithm>
#include <cstddef>
#include <vector>

#include "fresnel.hpp"

namespace lucent::optics {

template <class T>
class FtTable {
 public:
  explicit FtTable(T eta, std::size_t nodes = 256) : mValues(std::max<std::size_t>(nodes, 2)) {
    for (std::size_t i = 0; i < mValues.size(); ++i)
      mValues[i] = fresnelTransmittance(T(i) / T(mValues.size() - 1), eta);
  }
  /// Ft at cos(theta) in [0, 1] (clamped).
  T operator()(T cosTheta) const {
    const T u = std::clamp(cosTheta, T(0), T(1)) * T(mValues.size() - 1);
    const std::size_t i = std::min<std::size_t>(std::size_t(u), mValues.size() - 2);
    const T f = u - T(i);
    return mValues[i] * (T(1) - f) + mValues[i + 1] * f;
  }
  const std::vector<T>& values() const { return mValues; }

 private:
  std::vector<T> mValues;
};

}  // namespace lucent::optics
