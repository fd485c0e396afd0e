#pragma once
/// @file dynamic_rd_table.hpp
/// @brief Dynamic material and size (Chang et al. 2008 Sec. 5.1): the 1-D Rd texture
/// becomes 2-D, Rd(r, t), where t in [0, 1] interpolates the scattering coefficients (sigma_a, sigma_s',
/// eta) and the model size linearly from setting A to setting B, as the paper does.
///
/// Scaling the object by k(t) = size(t)/size(0) scales distances by k and areas (hence each sample's
/// power E' dA for a directional light) by k^2, so with samples drawn once at size(0),
///   B_t(x_o) = sum_i w_i k^2 Rd_t(k r_i),
/// and the table stores T(r, t) = k(t)^2 Rd_t(k(t) r) over the base-size distance r: changing material
/// or size is one texture lookup, no new atlas and no new samples.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "../optics/dipole.hpp"
#include "../optics/materials.hpp"

namespace lucent::atlas {

struct ScatteringSetting {
  optics::Rgb<double> sigmaA{0}, sigmaSPrime{1};
  double eta = 1.3;
  double sizeScale = 1;  ///< object size relative to the size the samples were drawn at
};

class DynamicRdTable {
 public:
  /// @param rows t nodes (>= 2), @param columns r nodes (>= 2), on u = sqrt(r / rMax) like RdTable.
  DynamicRdTable(const ScatteringSetting& a, const ScatteringSetting& b, double rMax, std::size_t rows = 64,
                 std::size_t columns = 1024)
      : mA(a), mB(b), mRMax(rMax), mRows(rows), mColumns(columns) {
    if (rows < 2 || columns < 2) throw std::invalid_argument("DynamicRdTable needs at least 2 x 2 nodes");
    if (!(rMax > 0) || !(a.sizeScale > 0) || !(b.sizeScale > 0))
      throw std::invalid_argument("DynamicRdTable: rMax and the size scales must be > 0");
    mValues.resize(rows * columns);
    for (std::size_t j = 0; j < rows; ++j) {
      const double t = double(j) / double(rows - 1);
      for (std::size_t i = 0; i < columns; ++i) {
        const double s = double(i) / double(columns - 1);
        mValues[j * columns + i] = exact(mRMax * s * s, t);
      }
    }
  }

  /// The setting at t: coefficients and size interpolated linearly.
  ScatteringSetting settingAt(double t) const {
    t = std::clamp(t, 0.0, 1.0);
    ScatteringSetting s;
    s.sigmaA = (1 - t) * mA.sigmaA + t * mB.sigmaA;
    s.sigmaSPrime = (1 - t) * mA.sigmaSPrime + t * mB.sigmaSPrime;
    s.eta = (1 - t) * mA.eta + t * mB.eta;
    s.sizeScale = (1 - t) * mA.sizeScale + t * mB.sizeScale;
    return s;
  }

  /// k^2 Rd_t(k r) evaluated directly (what the table approximates; also the test's reference).
  optics::Rgb<double> exact(double r, double t) const {
    const ScatteringSetting s = settingAt(t);
    const auto d = optics::Dipole<double>::make(s.sigmaA, s.sigmaSPrime, s.eta);
    return d.rd(s.sizeScale * r) * (s.sizeScale * s.sizeScale);
  }

  /// Bilinear lookup, as a GPU 2-D texture with u = sqrt(r / rMax) and v = t; 0 beyond rMax.
  optics::Rgb<double> operator()(double r, double t) const {
    if (!(r >= 0) || r > mRMax) return optics::Rgb<double>(0);
    const double u = std::sqrt(r / mRMax) * double(mColumns - 1), v = std::clamp(t, 0.0, 1.0) * double(mRows - 1);
    const std::size_t i = std::min<std::size_t>(std::size_t(u), mColumns - 2);
    const std::size_t j = std::min<std::size_t>(std::size_t(v), mRows - 2);
    const double fu = u - double(i), fv = v - double(j);
    auto at = [&](std::size_t jj, std::size_t ii) { return mValues[jj * mColumns + ii]; };
    return (at(j, i) * (1 - fu) + at(j, i + 1) * fu) * (1 - fv) + (at(j + 1, i) * (1 - fu) + at(j + 1, i + 1) * fu) * fv;
  }

  std::size_t rows() const { return mRows; }
  std::size_t columns() const { return mColumns; }
  double rMax() const { return mRMax; }

 private:
  ScatteringSetting mA, mB;
  double mRMax;
  std::size_t mRows, mColumns;
  std::vector<optics::Rgb<double>> mValues;
};

/// A measured material as a setting at a size scale.
inline ScatteringSetting settingOf(const optics::Material& m, double sizeScale = 1) {
  return {m.sigmaA, m.sigmaSPrime, m.eta, sizeScale};
}

}  // namespace lucent::atlas
