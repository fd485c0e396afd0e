#pragma once
/// @file sparse_vector.hpp
/// @brief Non-linear wavelet approximation (keep the k largest coefficients; Ng, Ramamoorthi,
/// Hanrahan 2003) of an RGB vector of cube-map Haar coefficients, its 16-bit quantisation with a
/// stated error bound, and the sparse dot products relighting is made of.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include <glm/vec3.hpp>

#include "haar.hpp"

namespace lucent::prt {

/// How coefficients compete for the k kept places.
enum class Selection {
  Magnitude,     ///< the largest |c| (the L2-optimal choice for the vector itself)
  AreaWeighted,  ///< the largest |c| times the area of the coefficient's support, which favours the
                 ///< coarse terms a smooth transport vector weighs most (Ng et al. 2003, Sec. 5)
};

/// The kept coefficients, sorted by index: scalar (a grey irradiance transport vector) or RGB.
template <class V>
struct Sparse {
  std::vector<std::uint32_t> index;
  std::vector<V> value;
  std::size_t size() const { return index.size(); }
};
using SparseVector = Sparse<glm::vec3>;
using SparseScalars = Sparse<float>;

inline double largestChannel(float c) { return std::abs(double(c)); }
inline double largestChannel(const glm::vec3& c) {
  return std::max(std::abs(double(c.x)), std::max(std::abs(double(c.y)), std::abs(double(c.z))));
}

/// The k coefficients of `dense` (6 faces of faceSize^2 Haar coefficients) with the largest scores;
/// zeros are never kept. k >= the count keeps every non-zero coefficient.
template <class V>
Sparse<V> keepLargest(const std::vector<V>& dense, int faceSize, std::size_t k,
                      Selection selection = Selection::Magnitude) {
  const std::size_t face = std::size_t(faceSize) * faceSize;
  std::vector<double> score(dense.size());
  std::vector<std::uint32_t> order;
  for (std::size_t i = 0; i < dense.size(); ++i) {
    double side = 1;
    if (selection == Selection::AreaWeighted) {
      const std::size_t inFace = i % face;
      side = supportSide(int(inFace / faceSize), int(inFace % faceSize), faceSize);
    }
    score[i] = largestChannel(dense[i]) * side * side;
    if (score[i] > 0) order.push_back(std::uint32_t(i));
  }
  if (k < order.size()) {
    std::nth_element(order.begin(), order.begin() + std::ptrdiff_t(k), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return score[a] > score[b]; });
    order.resize(k);
  }
  std::sort(order.begin(), order.end());
  Sparse<V> out;
  out.index = order;
  out.value.reserve(order.size());
  for (std::uint32_t i : order) out.value.push_back(dense[i]);
  return out;
}

/// sum over the kept coefficients of a[i] * dense[i], per channel.
inline glm::dvec3 dot(const SparseVector& a, const std::vector<glm::vec3>& dense) {
  glm::dvec3 sum(0);
  for (std::size_t i = 0; i < a.size(); ++i)
    sum += glm::dvec3(a.value[i]) * glm::dvec3(dense[a.index[i]]);
  return sum;
}

/// A sparse vector with 16-bit values: value = q * scale per channel, scale = max |c| / 32767, so
/// each coefficient is off by at most scale / 2 (`bound`), and a dot product with a vector l by at
/// most (scale / 2) * sum |l_i| over the kept indices.
struct QuantizedVector {
  std::vector<std::uint32_t> index;
  std::vector<std::int16_t> q;  ///< 3 per index, RGB
  glm::dvec3 scale{0};

  static constexpr double kLevels = 32767;

  glm::dvec3 bound() const { return scale * 0.5; }
  std::size_t bytes() const {
    return index.size() * (sizeof(std::uint32_t) + 3 * sizeof(std::int16_t));
  }
  glm::dvec3 value(std::size_t i) const {
    return glm::dvec3(q[3 * i], q[3 * i + 1], q[3 * i + 2]) * scale;
  }
};

inline QuantizedVector quantize(const SparseVector& v) {
  QuantizedVector out;
  out.index = v.index;
  glm::dvec3 largest(0);
  for (const glm::vec3& c : v.value)
    for (int ch = 0; ch < 3; ++ch) largest[ch] = std::max(largest[ch], std::abs(double(c[ch])));
  for (int ch = 0; ch < 3; ++ch)
    out.scale[ch] = largest[ch] > 0 ? largest[ch] / QuantizedVector::kLevels : 0;
  out.q.reserve(3 * v.size());
  for (const glm::vec3& c : v.value)
    for (int ch = 0; ch < 3; ++ch)
      out.q.push_back(out.scale[ch] > 0 ? std::int16_t(std::lround(c[ch] / out.scale[ch])) : 0);
  return out;
}

inline glm::dvec3 dot(const QuantizedVector& a, const std::vector<glm::vec3>& dense) {
  glm::dvec3 sum(0);
  for (std::size_t i = 0; i < a.index.size(); ++i)
    sum += a.value(i) * glm::dvec3(dense[a.index[i]]);
  return sum;
}

}  // namespace lucent::prt
