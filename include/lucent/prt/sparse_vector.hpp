#pragma once
/// @file sparse_vector.hpp
/// @brief Non-linear wavelet approximation (keep the k largest coefficients; Ng, Ramamoorthi,
/// Hanrahan 2003) of an RGB vector of cube-map Haar coefficients, its 16-bit quantisation with a
/// stated error bound, and the sparse dot products relighting is made of.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <vector>

#include <glm/vec3.hpp>

#include "../util/simd.hpp"
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
/// most (scale / 2) * sum |l_i| over the kept indices. Indices are 16-bit too: a cube 64 across
/// has 24576 texels. A frame streams these bytes (bench/prt_dot_bench: the dot products run near
/// the memory bandwidth), so 8 bytes a term rather than 10 is a fifth off the frame as well.
struct QuantizedVector {
  using Index = std::uint16_t;
  static constexpr std::size_t kMaxTexels = std::size_t(1) << 16;
  std::vector<Index> index;
  std::vector<std::int16_t> q;  ///< 3 per index, RGB
  glm::dvec3 scale{0};

  static constexpr double kLevels = 32767;

  glm::dvec3 bound() const { return scale * 0.5; }
  std::size_t bytes() const { return index.size() * (sizeof(Index) + 3 * sizeof(std::int16_t)); }
  glm::dvec3 value(std::size_t i) const {
    return glm::dvec3(q[3 * i], q[3 * i + 1], q[3 * i + 2]) * scale;
  }
};

inline QuantizedVector quantize(const SparseVector& v) {
  QuantizedVector out;
  out.index.reserve(v.size());
  for (const std::uint32_t i : v.index) {
    if (i >= QuantizedVector::kMaxTexels)
      throw std::length_error("a transport vector's index does not fit 16 bits (a cube over 64)");
    out.index.push_back(QuantizedVector::Index(i));
  }
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

/// A frame's dense light coefficients split into channels once, so that the dot products below
/// vectorise: one gather per channel and term.
struct LightChannels {
  std::vector<float> r, g, b;
  explicit LightChannels(const std::vector<glm::vec3>& light)
      : r(light.size()), g(light.size()), b(light.size()) {
    for (std::size_t i = 0; i < light.size(); ++i)
      r[i] = light[i].x, g[i] = light[i].y, b[i] = light[i].z;
  }
};

/// sum_i q_i scale l_{index_i} per channel, accumulated in double; vectorised (AVX2 gathers where
/// the CPU has them, util/simd.hpp).
LUCENT_VECTOR_CLONES inline glm::dvec3 dot(const QuantizedVector& a, const LightChannels& light) {
  const QuantizedVector::Index* index = a.index.data();
  const std::int16_t* q = a.q.data();
  const float *lr = light.r.data(), *lg = light.g.data(), *lb = light.b.data();
  const std::size_t n = a.index.size();
  double r = 0, g = 0, b = 0;
#pragma omp simd reduction(+ : r, g, b)
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = index[i];
    r += double(q[3 * i]) * double(lr[k]);
    g += double(q[3 * i + 1]) * double(lg[k]);
    b += double(q[3 * i + 2]) * double(lb[k]);
  }
  return glm::dvec3(r, g, b) * a.scale;
}

}  // namespace lucent::prt
