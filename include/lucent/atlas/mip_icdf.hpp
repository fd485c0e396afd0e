#pragma once
/// @file mip_icdf.hpp
/// @brief Importance sampling of texels in proportion to a non-negative image (the atlas irradiance
/// E'), Chang et al. 2008 Sec. 3.2, Fig. 2:
///  - MipIcdf (Fig. 2b): a pyramid of sums; a sample descends from the 1x1 top, choosing among
///    the four children by their sums. Here the choice warps one 2-D point hierarchically (first
///    left/right by column sums, then top/bottom within the chosen column, rescaling the point each
///    time; Clarberg et al. 2005), so stratified or low-discrepancy inputs stay well distributed
///    (the paper used independent random numbers per level).
///  - RowIcdf (Fig. 2a): marginal CDF over rows, then the conditional CDF within the row.
/// Both return the texel and its probability p = value / sum, i.e. E'/(E'avg N texels) of Eq. 9,
/// and a continuous position inside the texel. An all-zero image (light behind the object) samples
/// nothing.
#include <algorithm>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <vector>

namespace lucent::atlas {

struct TexelSample {
  int x = 0, y = 0;        ///< texel
  double u = 0, v = 0;     ///< position in [0, width) x [0, height), inside the texel
  double probability = 0;  ///< of choosing this texel: value / sum (> 0 for any returned sample)
};

class MipIcdf {
 public:
  /// @param values row-major width*height, >= 0 (negative or NaN values are treated as 0)
  MipIcdf(int width, int height, const std::vector<float>& values)
      : mWidth(width), mHeight(height) {
    if (width <= 0 || height <= 0 || values.size() != std::size_t(width) * std::size_t(height))
      throw std::invalid_argument("MipIcdf: values must hold width*height entries");
    mSize = 1;
    while (mSize < std::max(width, height))
      mSize *= 2;  // padded with zeros to a square power of two
    // The finest level stays float, as given (half the memory of double, which a frame touches
    // fresh); the sums above it are double, so rounding does not grow with the texel count.
    mFinest.resize(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) mFinest[i] = values[i] > 0 ? values[i] : 0.0f;
    for (int s = mSize; s > 1; s /= 2) {
      const int h = s / 2;
      std::vector<double> up(std::size_t(h) * h);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < h; ++x)
          up[std::size_t(y) * h + x] =
              at(mLevels.size(), 2 * x, 2 * y) + at(mLevels.size(), 2 * x + 1, 2 * y) +
              at(mLevels.size(), 2 * x, 2 * y + 1) + at(mLevels.size(), 2 * x + 1, 2 * y + 1);
      mLevels.push_back(std::move(up));
    }
    std::reverse(mLevels.begin(), mLevels.end());  // mLevels[0] is the 1x1 total
  }

  double total() const { return mLevels.empty() ? double(mFinest[0]) : mLevels.front()[0]; }

  /// Maps (u1, u2) in [0,1)^2 to a texel with probability value/total; nothing when the image is
  /// all zero.
  std::optional<TexelSample> sample(double u1, double u2) const {
    if (!(total() > 0)) return std::nullopt;
    int x = 0, y = 0;
    const std::size_t finest = mLevels.size();  // the level index of mFinest, counted from the top
    for (std::size_t l = 1; l <= finest; ++l) {
      auto value = [&](int cx, int cy) { return levelValue(l, cx, cy); };
      const int x0 = 2 * x, y0 = 2 * y;
      const double left = value(x0, y0) + value(x0, y0 + 1),
                   right = value(x0 + 1, y0) + value(x0 + 1, y0 + 1);
      const double pLeft = left / (left + right);
      int cx;
      if (u1 < pLeft)
        cx = x0, u1 = u1 / pLeft;
      else
        cx = x0 + 1, u1 = (u1 - pLeft) / (1 - pLeft);
      const double top = value(cx, y0), bottom = value(cx, y0 + 1);
      const double pTop = top / (top + bottom);
      int cy;
      if (u2 < pTop)
        cy = y0, u2 = u2 / pTop;
      else
        cy = y0 + 1, u2 = (u2 - pTop) / (1 - pTop);
      x = cx, y = cy;
      u1 = std::clamp(u1, 0.0, 1.0 - 1e-16), u2 = std::clamp(u2, 0.0, 1.0 - 1e-16);
    }
    return TexelSample{x, y, x + u1, y + u2, finestValue(x, y) / total()};
  }

  int width() const { return mWidth; }
  int height() const { return mHeight; }
  int levels() const { return int(mLevels.size()) + 1; }

 private:
  /// The finest level's value at (x, y) of the padded square: 0 in the padding.
  double finestValue(int x, int y) const {
    return x < mWidth && y < mHeight ? double(mFinest[std::size_t(y) * mWidth + x]) : 0.0;
  }
  /// The value at (x, y) of level l counted from the top (l = mLevels.size() is the finest).
  double levelValue(std::size_t l, int x, int y) const {
    if (l == mLevels.size()) return finestValue(x, y);
    return mLevels[l][std::size_t(y) * (std::size_t(1) << l) + x];
  }
  /// While building (levels still stored finest-first): the value at (x, y) of the level `built`
  /// levels above the finest.
  double at(std::size_t built, int x, int y) const {
    if (built == 0) return finestValue(x, y);
    const auto& lv = mLevels[built - 1];
    const std::size_t side = std::size_t(mSize) >> built;
    return lv[std::size_t(y) * side + x];
  }

  int mWidth, mHeight, mSize = 1;
  std::vector<float> mFinest;                ///< the image, negative and NaN values set to 0
  std::vector<std::vector<double>> mLevels;  ///< the sums, 1x1 first (without the finest level)
};

class RowIcdf {
 public:
  RowIcdf(int width, int height, const std::vector<float>& values)
      : mWidth(width), mHeight(height) {
    if (width <= 0 || height <= 0 || values.size() != std::size_t(width) * std::size_t(height))
      throw std::invalid_argument("RowIcdf: values must hold width*height entries");
    mRowCdf.assign(std::size_t(height) + 1, 0.0);
    mCdf.assign(std::size_t(height) * (width + 1), 0.0);
    for (int y = 0; y < height; ++y) {
      double* c = &mCdf[std::size_t(y) * (width + 1)];
      for (int x = 0; x < width; ++x) {
        const float v = values[std::size_t(y) * width + x];
        c[x + 1] = c[x] + (v > 0 ? double(v) : 0.0);
      }
      mRowCdf[std::size_t(y) + 1] = mRowCdf[std::size_t(y)] + c[width];
    }
  }

  double total() const { return mRowCdf.back(); }

  std::optional<TexelSample> sample(double u1, double u2) const {
    if (!(total() > 0)) return std::nullopt;
    // Row: the first y with rowCdf[y+1] > u2 * total (binary search), skipping empty rows.
    const double targetRow = u2 * total();
    const int y = int(std::upper_bound(mRowCdf.begin() + 1, mRowCdf.end(), targetRow) -
                      (mRowCdf.begin() + 1));
    const int row = std::min(y, mHeight - 1);
    const double* c = &mCdf[std::size_t(row) * (mWidth + 1)];
    const double rowSum = c[mWidth];
    const double targetCol = u1 * rowSum;
    const int x =
        std::min(int(std::upper_bound(c + 1, c + mWidth + 1, targetCol) - (c + 1)), mWidth - 1);
    const double value = c[x + 1] - c[x];
    const double fx = value > 0 ? (targetCol - c[x]) / value : 0.5;
    const double rowValue = mRowCdf[std::size_t(row) + 1] - mRowCdf[std::size_t(row)];
    const double fy = rowValue > 0 ? (targetRow - mRowCdf[std::size_t(row)]) / rowValue : 0.5;
    return TexelSample{x, row, x + std::clamp(fx, 0.0, 1.0 - 1e-16),
                       row + std::clamp(fy, 0.0, 1.0 - 1e-16), value / total()};
  }

 private:
  int mWidth, mHeight;
  std::vector<double> mRowCdf, mCdf;
};

}  // namespace lucent::atlas
